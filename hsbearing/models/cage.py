"""The guide-land film law at its public path ``hsbearing.models.cage`` (a contract of the API since the second
round): the physics lives in :mod:`hsbearing.models.ball_bearing.cage`; this module re-exports its public names."""

from hsbearing.models.ball_bearing.cage import *  # noqa: F401,F403
from hsbearing.models.ball_bearing.cage import __all__  # noqa: F401
