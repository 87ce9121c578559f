"""Design codes: procedures on spectra, beside the models (docs/isolation_design.md).

- :mod:`~stickslip.codes.damping`: the codes' damping factors (ASCE 7-22's
  B_M, AASHTO's B_L, EN 1998-1's η);
- :mod:`~stickslip.codes.target_spectra`: the codes' elastic spectra (ASCE
  7-22's two-period spectrum or a multi-period table, AASHTO's three-point
  spectrum, EN 1998-1's type 1 and 2 spectra), each with its damping;
- :mod:`~stickslip.codes.friction_pendulum`: the equivalent-lateral-force
  design of a friction pendulum by each code, at nominal, upper- and
  lower-bound friction;
- :mod:`~stickslip.codes.suite_scaling`: a suite of station pairs scaled to
  a target spectrum over the period range around T_M, and the suite's
  statistic (the mean of seven pairs or more, else the maximum);
- :mod:`~stickslip.codes.response_history`: the scaled suite solved exactly
  on the friction pendulum in the plane at both bounds, beside the ELF values.

The spectra of records come from :mod:`stickslip.spectra`.
"""
