"""Design codes: procedures on spectra, beside the models (docs/isolation_design.md).

- :mod:`~stickslip.codes.damping`: the codes' damping factors (ASCE 7-22's
  B_M, AASHTO's B_L, EN 1998-1's η);
- :mod:`~stickslip.codes.target_spectra`: the codes' elastic spectra (ASCE
  7-22's two-period spectrum or a multi-period table, AASHTO's three-point
  spectrum, EN 1998-1's type 1 and 2 spectra), each with its damping;
- :mod:`~stickslip.codes.friction_pendulum`: the equivalent-lateral-force
  design of a friction pendulum by each code, at nominal, upper- and
  lower-bound friction.

The spectra of records come from :mod:`stickslip.spectra`.
"""
