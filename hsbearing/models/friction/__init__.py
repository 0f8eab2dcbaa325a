"""Friction-moment physics of ball bearings: SKF 2004 (``skf2004``), the seed 003 sliding method with pure
rolling lines (``sliding_prl``), the gyro bearing (``gyro``, seed 000) and the wire-race bearing
(``wire_race``, seed 001).

The case-level drivers are the systems: the deep-groove friction torque over speeds is
:mod:`hsbearing.systems.deep_groove.friction`, the gyro model and studies :mod:`hsbearing.systems.gyro`, the
preload sweep :mod:`hsbearing.systems.wire_race`.
"""
