"""The structure that sliders carry or sit on: a linear shear building and its exact linear response.

:mod:`~stickslip.solvers.structure.shear_building` builds the building (floor
masses, story stiffnesses, its fixed-base modes and damping);
:mod:`~stickslip.solvers.structure.linear_response` gives the exact response of
any linear structure to a ground acceleration linear between samples (the
fixed-base building, the bare building under a damper, the building with the
damper's mass attached); :mod:`~stickslip.solvers.structure.friction_linked`
the exact response of a linear structure linked by one friction interface
(the isolated building and the friction tuned mass damper are instances), in
one direction; :mod:`~stickslip.solvers.structure.integrated` the same
structure in the plane, with the vertical motion and μ(v), integrated to a
tolerance with its events located (the slip's equation in
:mod:`~stickslip.solvers.structure.slip_equation`, the event loop in
:mod:`~stickslip.solvers.structure.integrated_events`, its steps in
:mod:`~stickslip.solvers.structure.integrated_step`).
"""
