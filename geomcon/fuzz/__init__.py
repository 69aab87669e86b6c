"""Seeded fuzzing: hostile mutations of problem files and random valid problems of every recipe family.

``geomcon fuzz`` (and ``tests/test_fuzz.py`` with small counts) runs both and counts internal errors,
false exits 1, wrong answers, malformed error lines and partial files; every count must be 0.

The valid-problem generators live one module per family (``valid_*.py``); each exports ``GENERATORS``, a
mapping ``name -> generator``, where a generator takes a :class:`random.Random` and returns a
:class:`~geomcon.fuzz.case.ValidCase`.
"""
