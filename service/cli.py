"""The ``tensegrity-opt`` console script: the library's commands plus the service's ``serve`` and ``openapi``.

``serve`` starts the HTTP service (uvicorn, one process; settings from ``TENSEGRITY_*`` environment
variables) and ``openapi`` prints its OpenAPI document; every other command (``buckling``,
``equilibrium``, ``plot``, ``sweep``, ...) is the library's (:func:`tensegrity_opt.applications.cli.main`,
same parser, same output). This module sits above both: the library never imports the service.

The service's packages (FastAPI, uvicorn, ...) are the ``service`` extra; they are imported only
when a service command runs, so the library's commands work without them, and ``serve`` /
``openapi`` without them print one line naming the extra and exit with status 2.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from tensegrity_opt.applications import cli as library_cli

__all__ = ["main", "build_parser", "add_service_commands", "EXTRA"]

#: How to install what ``serve`` and ``openapi`` need.
EXTRA = "pip install 'tensegrity-opt[service]'"


def _missing_extra(exc: ImportError) -> int:
    name = getattr(exc, "name", None) or str(exc)
    print(f"tensegrity-opt: error: the HTTP service needs the 'service' extra ({name} is not installed): {EXTRA}",
          file=sys.stderr)
    return 2


def _cmd_serve(args: argparse.Namespace) -> int:
    try:
        import uvicorn

        from .api.connections import uvicorn_options
        from .config import Settings
        from .main import create_app
    except ImportError as exc:
        return _missing_extra(exc)
    try:
        settings = Settings()
    except ValueError as exc:
        print(f"tensegrity-opt: error: invalid TENSEGRITY_* setting: {exc}", file=sys.stderr)
        return 2
    # One process: its executors (solver threads and processes) supply the parallelism (service/execution/).
    # Connection limits (request timeout, connection cap, keep-alive, concurrency): service/api/connections.py.
    uvicorn.run(create_app(settings), host=args.host, port=args.port, log_level=args.log_level,
                access_log=not args.no_access_log, workers=1,
                timeout_graceful_shutdown=settings.shutdown_timeout, **uvicorn_options(settings))
    return 0


def _cmd_openapi(args: argparse.Namespace) -> int:
    try:
        from .main import openapi_json
    except ImportError as exc:
        return _missing_extra(exc)
    sys.stdout.write(openapi_json())
    return 0


def _port(text: str) -> int:
    """An argparse type: a TCP port 1-65535, else a usage error (exit 2)."""
    try:
        v = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a TCP port 1-65535, got {text!r}") from None
    if not 1 <= v <= 65535:
        raise argparse.ArgumentTypeError(f"expected a TCP port 1-65535, got {v}")
    return v


def add_service_commands(sub: Any) -> None:
    """``serve`` and ``openapi`` on the subparsers ``sub`` of the library's parser."""
    sp = sub.add_parser("serve", help="start the HTTP service (uvicorn, one process; TENSEGRITY_* settings); "
                                      "it runs until Ctrl-C, so start it in a second terminal or with &")
    sp.add_argument("--host", default="127.0.0.1", help="interface to bind")
    sp.add_argument("--port", type=_port, default=8000, help="TCP port (1-65535)")
    sp.add_argument("--log-level", default="info", choices=("critical", "error", "warning", "info", "debug"),
                    help="uvicorn's log level")
    sp.add_argument("--no-access-log", action="store_true", help="do not log every request")
    sp.set_defaults(run=_cmd_serve)

    sp = sub.add_parser("openapi", help="print the service's OpenAPI document (JSON, sorted keys, indent 2)")
    sp.set_defaults(run=_cmd_openapi)


def build_parser() -> argparse.ArgumentParser:
    """The library's parser with the service's commands added."""
    return library_cli.build_parser(add_commands=add_service_commands)


def main(argv: list[str] | None = None) -> int:
    """Run one command (``argv``: ``sys.argv[1:]`` by default); the exit status."""
    return library_cli.main(argv, parser=build_parser())


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
