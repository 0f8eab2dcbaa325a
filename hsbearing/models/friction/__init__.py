"""Friction-moment physics of ball bearings: SKF 2004 (``skf2004``), the dgbb_prl sliding method with pure
rolling lines (``sliding_prl``), the gyro bearing (``gyro``, Jiang et al. 2014) and the wire-race bearing
(``wire_race``, Shan et al. 2010).

The case-level drivers are the systems: the deep-groove friction torque over speeds is
:mod:`hsbearing.systems.deep_groove.friction`, the gyro model and studies :mod:`hsbearing.systems.gyro`, the
preload sweep :mod:`hsbearing.systems.wire_race`.
"""
