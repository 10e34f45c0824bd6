"""``python -m service serve|openapi|...``: the ``tensegrity-opt`` console script (:mod:`service.cli`)."""

import sys

from .cli import main

sys.exit(main())
