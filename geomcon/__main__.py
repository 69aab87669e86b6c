"""``python -m geomcon``: the same as the ``geomcon`` command."""
from .cli import main

raise SystemExit(main())
