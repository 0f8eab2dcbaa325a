"""``python -m hsbearing.cli``: the same as the ``hsbearing`` command."""

import sys

from hsbearing.cli import main

sys.exit(main())
