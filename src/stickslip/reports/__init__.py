"""Presentation that pages share: figures, the reports' index page and the paper's list of tables and figures.

Nothing here computes a result: every function draws or lays out numbers that
the library's computing modules produced and the workflow wrote to files. A
study's own figures and index section live in its package, :mod:`stickslip.studies`.

- :mod:`~stickslip.reports.plots`: shared figure helpers and the figures of one
  response, one record and the paper's studies;
- :mod:`~stickslip.reports.model_plots`: the paper's model figures (Figs. 2, 3,
  11-12, 16);
- :mod:`~stickslip.reports.design_answer` and :mod:`~stickslip.reports.design_plots`:
  one record's design answer (:mod:`stickslip.optimum`) as ``stickslip optimum`` prints
  it and as the record report shows and draws it;
- :mod:`~stickslip.reports.index_page`: ``reports/index.html``, with each study's section
  from its package and :mod:`~stickslip.reports.paper_items` for its account of the paper's items;
- :mod:`~stickslip.reports.suite_page`: ``stickslip isolation suite``'s text
  table, figure and page, from its document;
- :mod:`~stickslip.reports.isolator_plots`: the friction pendulum's design chart;
- :mod:`~stickslip.reports.pages_index`: the ``index.html`` of a folder of pages that
  ``stickslip report`` writes.
"""
