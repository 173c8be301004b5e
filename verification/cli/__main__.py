"""``python -m verification.cli``: the ``riser-verify`` command."""

import sys

from . import main

sys.exit(main())
