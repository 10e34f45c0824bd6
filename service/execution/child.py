"""``python -m service.execution.child FD``: a solver process (:func:`service.execution.ipc.serve`)."""

import sys

from .ipc import serve

if __name__ == "__main__":
    serve(int(sys.argv[1]))
