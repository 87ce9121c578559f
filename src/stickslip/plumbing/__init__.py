"""What the workflow and the writers share, kept out of the public API at the package root.

- :mod:`~stickslip.plumbing.config`: the workflow configuration's checks (the schema and what it cannot say);
- :mod:`~stickslip.plumbing.files`: atomic writes, CSV tables and the provenance stored with every result;
- :mod:`~stickslip.plumbing.step`: the one script every computing rule runs;
- :mod:`~stickslip.plumbing.dependencies`: which library files a rule depends on, read from the imports.
"""
