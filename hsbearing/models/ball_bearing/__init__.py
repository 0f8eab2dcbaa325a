"""Physics of a ball bearing with balls, cage and rings (the 6-DOF model of Zhang et al. 2016,
Eqs. 5-21, and the high-speed quasi-static model): force and moment laws, the compiled
right-hand side (kernel), its state layout and named parameters/outputs (kernel_io).
The driver of each module of the same name is in :mod:`hsbearing.systems.angular_contact`."""
