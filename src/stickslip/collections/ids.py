"""Record ids of a collection: stable, and safe as file names and Snakemake wildcards.

An id is the record's description (event and record name, or a file's stem)
in lower case, with every run of characters other than ``a-z`` and ``0-9``
replaced by one underscore and none at either end:
``("Chi-Chi, Taiwan 1999", "CHY080-000")`` gives ``chi_chi_taiwan_1999_chy080_000``.
Such an id contains no ``/``, blank, comma, dot or brace, so it is a valid
file name on every system and matches a wildcard without constraints; it
depends only on the description, so it does not change when records are
added to or removed from a collection.
"""

from __future__ import annotations

import re

#: What every id matches.
ID_PATTERN = re.compile(r"^[a-z0-9]+(?:_[a-z0-9]+)*$")


def record_id(*parts: str) -> str:
    """The id of a record described by ``parts`` (for example event and record name)."""
    text = "_".join(str(part) for part in parts)
    slug = re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_")
    if not slug:
        raise ValueError(f"no letter or digit in {parts!r}: cannot make a record id")
    return slug


def duplicated_ids(ids) -> list[str]:
    """The ids that occur more than once in ``ids``, sorted."""
    seen: set[str] = set()
    twice: set[str] = set()
    for value in ids:
        (twice if value in seen else seen).add(value)
    return sorted(twice)
