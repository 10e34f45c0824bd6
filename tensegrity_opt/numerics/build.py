"""Generated C for CasADi Functions: compiled once per machine, loaded once per process, CasADi's VM otherwise.

Every compiled part of the numerics (the Newton kernels of :mod:`.kernels`, the path system of
:mod:`.path_system`, the inverse-statics step of :mod:`.inverse_statics`) comes through :func:`load`:

* the Functions are generated to C (``casadi.CodeGenerator``) and compiled with the system C compiler into
  ``TENSEGRITY_CACHE_DIR`` (default ``$XDG_CACHE_HOME/tensegrity_opt`` or ``~/.cache/tensegrity_opt``), one
  shared library per name, its file named by a hash of the generated code and the compiler command, so an
  upgrade never loads stale code; a library already there is loaded without compiling;
* the library's path is found once per process (under a lock per name: concurrent threads wait for the
  first one's build); every call returns new ``Function`` instances for the calling thread (a CasADi
  Function evaluates in its own memory and must not be called by two threads at once);
* without a compiler (``$CC`` or the first of ``cc``, ``gcc``, ``clang`` on the ``PATH``), with
  ``TENSEGRITY_COMPILE=0`` (or ``false``, ``no``, ``off``), or when compiling or loading fails, the same
  Functions run in CasADi's virtual machine: slower (about 4x for the Newton kernels), same results, never
  an error for the caller; one ``RuntimeWarning`` per process says so and why.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import tempfile
import threading
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import casadi as ca

__all__ = ["COMPILED", "VIRTUAL_MACHINE", "Loaded", "load", "libraries", "cache_dir", "compiler", "compiler_name"]

#: How loaded Functions run.
COMPILED = "compiled"
VIRTUAL_MACHINE = "virtual machine"

_FLAGS = ["-O2", "-fPIC", "-shared"]
_lock = threading.Lock()                    # guards the two tables below
_name_locks: dict[str, threading.Lock] = {}
#: Per process and library name: the compiled library's path, or ``""`` when its Functions run in the VM.
_libraries: dict[str, str] = {}
#: The Function names of each library (its ``graphs()`` keys), per process.
_names: dict[str, tuple[str, ...]] = {}
_warned = False


def _warn(why: str) -> None:
    """One warning per process: compiled Functions run in CasADi's virtual machine, and why."""
    global _warned
    with _lock:
        if _warned:
            return
        _warned = True
    warnings.warn(f"tensegrity_opt: {why}; the compiled functions (Newton kernels, path systems, inverse statics) "
                  "run in CasADi's virtual machine instead (slower: about 4x for the Newton kernels; same results)",
                  RuntimeWarning, stacklevel=4)


def cache_dir() -> Path:
    """Directory of the compiled libraries (``TENSEGRITY_CACHE_DIR`` or the user's cache directory)."""
    env = os.environ.get("TENSEGRITY_CACHE_DIR")
    if env:
        return Path(env)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "tensegrity_opt"


def _switched_off() -> str | None:
    """The value of ``TENSEGRITY_COMPILE`` when it switches compilation off (``0``, ``false``, ``no``, ``off``)."""
    value = os.environ.get("TENSEGRITY_COMPILE", "1")
    return value if value.strip().lower() in ("0", "false", "no", "off") else None


def compiler() -> str | None:
    """The C compiler used (``$CC`` or ``cc``/``gcc``/``clang``), or ``None`` (then no compilation)."""
    if _switched_off() is not None:
        return None
    cc = os.environ.get("CC")
    if cc:
        path = shutil.which(cc)
        if path is None:
            _warn(f"the C compiler CC={cc!r} was not found")
        return path
    for name in ("cc", "gcc", "clang"):
        path = shutil.which(name)
        if path:
            return path
    return None


def compiler_name() -> str | None:
    """The C compiler used by name and version (``"cc 12.2.0"``), not where it is installed; ``None``: none."""
    path = compiler()
    return None if path is None else _name_and_version(path)


@lru_cache(maxsize=8)
def _name_and_version(path: str) -> str:
    name = Path(path).name
    for flag in ("-dumpfullversion", "-dumpversion"):          # gcc knows both, clang the second
        try:
            out = subprocess.run([path, flag], capture_output=True, text=True, timeout=10, check=False)
        except (OSError, subprocess.SubprocessError):
            break
        version = out.stdout.strip().splitlines()[0] if out.returncode == 0 and out.stdout.strip() else ""
        if version and len(version) <= 40 and "/" not in version:
            return f"{name} {version}"
    return name


def libraries() -> dict[str, str]:
    """The libraries loaded so far in this process: name -> path (``""``: running in the virtual machine)."""
    with _lock:
        return dict(_libraries)


@dataclass(frozen=True)
class Loaded:
    """The calling thread's instances of a library's Functions (by name) and how they run (:data:`COMPILED`
    or :data:`VIRTUAL_MACHINE`)."""

    functions: dict[str, ca.Function]
    mode: str


def load(name: str, what: str, graphs: Callable[[], dict[str, ca.Function]]) -> Loaded:
    """The Functions ``graphs()`` (name -> Function, each named as its key) as compiled code, else in the VM.

    Parameters
    ----------
    name : str
        The library's name (one per set of Functions, e.g. ``tensegrity_kernels_n4``).
    what : str
        What the Functions are, for the warning (e.g. ``"the Newton kernels"``).
    graphs : callable
        Builds the Functions; called to generate the code (once per process) and for the virtual machine.
    """
    with _lock:
        name_lock = _name_locks.setdefault(name, threading.Lock())
    funcs = None
    with name_lock:
        path = _libraries.get(name)
        if path is None:
            funcs = graphs()
            _names[name] = tuple(funcs)
            path = _compile(name, what, funcs) or ""
            with _lock:
                _libraries[name] = path
    if path:
        try:
            return Loaded({key: ca.external(key, path) for key in _names[name]}, COMPILED)
        except RuntimeError as exc:                 # an unloadable library: never fatal
            _warn(f"loading {path} failed ({exc})")
            with _lock:
                _libraries[name] = ""
    return Loaded(funcs or graphs(), VIRTUAL_MACHINE)


def _compile(name: str, what: str, funcs: dict[str, ca.Function]) -> str | None:
    """Generate C for ``funcs``, compile it into the cache (once per machine); the library's path, or
    ``None`` (with the warning) when anything on the way fails."""
    cc = compiler()
    if cc is None:
        off = _switched_off()
        _warn(f"TENSEGRITY_COMPILE={off} switches compilation off" if off is not None else
              "no C compiler was found (CC, cc, gcc, clang; e.g. apt-get install gcc)")
        return None
    try:
        return _compile_with(cc, name, funcs)
    except (OSError, RuntimeError, subprocess.SubprocessError) as exc:
        detail = (getattr(exc, "stderr", None) or b"").decode(errors="replace")[:300]
        _warn(f"compiling {what} with {cc} failed ({exc} {detail})")
        return None


def _compile_with(cc: str, name: str, funcs: dict[str, ca.Function]) -> str:
    with tempfile.TemporaryDirectory(prefix="tensegrity-kernels-") as tmp:
        cg = ca.CodeGenerator(f"{name}.c", {"with_header": False})
        for f in funcs.values():
            cg.add(f)
        src_path = Path(cg.generate(tmp + os.sep))
        key = hashlib.sha256(src_path.read_bytes() + " ".join([cc, *_FLAGS, ca.__version__]).encode()).hexdigest()
        target = cache_dir() / f"{name}_{key[:16]}.so"
        if target.exists():
            return str(target)
        target.parent.mkdir(parents=True, exist_ok=True)
        tmp_so = Path(tmp) / "out.so"
        subprocess.run([cc, *_FLAGS, str(src_path), "-o", str(tmp_so), "-lm"], check=True, capture_output=True,
                       timeout=300)
        # atomic: concurrent processes may each compile; readers never see half a file
        staged = target.with_name(f"{target.name}.{os.getpid()}.{threading.get_ident()}.tmp")
        shutil.copyfile(tmp_so, staged)
        os.replace(staged, target)
        return str(target)
