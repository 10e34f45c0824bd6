"""``python -m tensegrity_opt.applications.cli``: the command line."""

import sys

from . import main

sys.exit(main())
