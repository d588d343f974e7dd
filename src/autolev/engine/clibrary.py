"""C compiled and loaded: the compiler, shared libraries built from C source (kept in
the build cache by the digest of source and flags), and a callable over a library's
function.  No sympy: a warm run from its run plan loads its libraries with this alone.
"""
from __future__ import annotations

import ctypes
import functools
import hashlib
import os
import platform
import shutil
import subprocess
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from .diskcache import cache_dir, install_or_aside, read_verified, verified
from .parentage import killed_with_parent

# without -fno-math-errno every sqrt may set errno, so gcc keeps each repeated call
# (the rider-lean bicycle repeats one 117 times); the values are the same bit for bit
C_FLAGS = ("-O1", "-fno-math-errno")

UNIT_MARK = "/* -- autolev: next translation unit -- */"
UNIT_STATEMENTS = 600    # a program this many statements per core is split


@functools.cache
def lanes_flags() -> tuple:
    """Flags for a program over several nodes at once (codegen's lanes): AVX2's
    four-wide operations where this processor has them, never a fused multiply-add
    (each lane then computes what one node's program computes, bit for bit)."""
    flags = ("-ffp-contract=off",)
    if platform.machine().lower() in ("x86_64", "amd64"):
        try:
            cpu = Path("/proc/cpuinfo").read_text()
        except OSError:         # not Linux: the vectors in SSE2's halves
            return flags
        if any(line.startswith("flags") and " avx2" in line for line in cpu.splitlines()):
            return flags + ("-mavx2", "-mno-fma")
    return flags


def cpus() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def compiler() -> str | None:
    """The C compiler to use ($CC, else cc or gcc), or None."""
    if os.environ.get("AUTOLEV_NO_C"):
        return None
    for cand in (os.environ.get("CC"), "cc", "gcc"):
        if cand and shutil.which(cand):
            return shutil.which(cand)
    return None


class CompileError(Exception):
    pass


@contextmanager
def _compiler_running():
    """A compiler the system cannot start (no process left on a loaded machine, a full
    temporary folder) as a failed compile: the caller's Python tier runs instead."""
    try:
        yield
    except OSError as exc:
        raise CompileError(f"the compiler could not run: {exc.strerror or exc}") from None


def build_object(source: str, flags: tuple) -> bytes:
    """Compile C source to an object file, cached by the hash of source and flags:
    code that is the same for every model (the integration loop) is compiled once.
    Returns its bytes (read as verified: another process's trim cannot take it away
    from a link under way)."""
    cc = compiler()
    if cc is None:
        raise CompileError("no C compiler")
    digest = hashlib.sha256((source + "\0" + " ".join(flags) + "\0" + cc).encode()).hexdigest()
    obj = cache_dir() / f"al_{digest[:24]}.o"
    data = read_verified(obj)
    if data is not None:
        return data
    with _compiler_running(), tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "shared.c"
        src.write_text(source)
        out = Path(tmp) / obj.name
        r = subprocess.run(killed_with_parent([cc, *flags, "-fPIC", "-c", "-o", str(out),
                                               str(src)]), capture_output=True, text=True)
        if r.returncode != 0:
            raise CompileError(r.stderr.strip()[-2000:])
        data = out.read_bytes()
        install_or_aside(data, obj)
    return data


def build_shared_library(source: str, flags: tuple | None = None,
                         shared_source: str = "") -> Path:
    """Compile C source to a shared library (cached by the hash of source and flags).
    A source made of several translation units (separated by UNIT_MARK) has them
    compiled in parallel.  -O1 by default: on the straight-line code models make it
    runs as fast as -O2 (planar 16-link: 2.6 against 2.5 us per evaluation) and
    compiles in about half the time."""
    cc = compiler()
    if cc is None:
        raise CompileError("no C compiler")
    flags = tuple(flags) if flags is not None else C_FLAGS
    digest = hashlib.sha256((source + "\0" + shared_source + "\0" + " ".join(flags) + "\0"
                             + cc).encode()).hexdigest()
    lib = cache_dir() / f"al_{digest[:24]}{'.dll' if sys.platform == 'win32' else '.so'}"
    if verified(lib):
        return lib
    # `shared_source`: compiled once for all models (its own cached object), linked in
    # at -O3: compiled once, and its loops (the LU solve, the stages) gain from it
    shared_flags = tuple("-O3" if f.startswith("-O") else f for f in flags)
    with _compiler_running(), tempfile.TemporaryDirectory() as tmp:
        shared = []
        if shared_source:
            shared.append(Path(tmp) / "shared.o")
            shared[0].write_bytes(build_object(shared_source, shared_flags))
        objects, procs = [], []
        for k, unit in enumerate(source.split(UNIT_MARK)):
            src = Path(tmp) / f"unit{k}.c"
            src.write_text(unit)
            obj = Path(tmp) / f"unit{k}.o"
            objects.append(obj)
            procs.append(subprocess.Popen(
                killed_with_parent([cc, *flags, "-fPIC", "-c", "-o", str(obj), str(src)]),
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True))
        errors = []
        for proc in procs:
            _, err = proc.communicate()
            if proc.returncode != 0:
                errors.append(err.strip())
        if errors:
            raise CompileError("\n".join(errors)[-2000:])
        out = Path(tmp) / lib.name
        r = subprocess.run(killed_with_parent([cc, "-shared", "-o", str(out),
                                               *map(str, objects + shared), "-lm"]),
                           capture_output=True, text=True)
        if r.returncode != 0:
            raise CompileError(r.stderr.strip()[-2000:])
        return install_or_aside(out.read_bytes(), lib)


def c_function(source: str, name: str, n_in: int, n_work: int, extra_source: str = "",
               extra_flags: tuple = (), lanes: int = 1):
    """The callable of `compile_c` from its source (compiled, or found in the cache);
    `lanes` > 1: a program over that many nodes at once, compiled for this processor."""
    flags = C_FLAGS + tuple(extra_flags) + (lanes_flags() if lanes > 1 else ())
    path = build_shared_library(source, flags, shared_source=extra_source)
    try:
        lib = ctypes.CDLL(str(path))
    except OSError as exc:          # (its bytes are verified: the loader lacked memory)
        raise CompileError(f"the compiled library {path.name} could not be loaded: "
                           f"{exc}") from None
    fn = getattr(lib, name)
    fn.argtypes = [ctypes.c_void_p] * (n_in + 2)
    fn.restype = None
    work = np.zeros(max(1, n_work))
    work_addr = work.ctypes.data
    empty = np.zeros(1)

    def address(a, keep):
        if len(a) == 0:
            return empty.ctypes.data
        if not (isinstance(a, np.ndarray) and a.dtype == np.float64
                and a.flags.c_contiguous):
            a = np.ascontiguousarray(a, dtype=float)
            keep.append(a)
        return a.ctypes.data

    def call(*arrays):
        keep: list = []                      # converted copies live until the call ends
        args = [address(a, keep) for a in arrays[:n_in]]
        out = arrays[-1]
        if len(out) and isinstance(out, np.ndarray) and out.dtype == np.float64 \
                and out.flags.c_contiguous:
            fn(*args, work_addr, out.ctypes.data)
            return out
        tmp = np.zeros(max(1, len(out)))
        fn(*args, work_addr, tmp.ctypes.data)
        if len(out):
            out[:] = tmp[:len(out)]
        return out
    rows_fn = lib[name + "_rows"]
    rows_fn.argtypes = ([ctypes.c_long, ctypes.c_void_p] + [ctypes.c_void_p] * (n_in + 2)
                        + [ctypes.c_long])
    rows_fn.restype = None

    def rows(arrays, per_row, out):
        """Every row of `out` (rows x outputs, C order) from the rows of the inputs that
        are `per_row` (2-D, C order) and the same vectors for the others."""
        keep: list = []
        step = np.array([a.shape[1] if each else 0 for a, each in zip(arrays, per_row)],
                        dtype=ctypes.c_long)
        rows_fn(len(out), step.ctypes.data, *[address(np.ravel(a), keep) for a in arrays],
                work_addr, out.ctypes.data, out.shape[1])
        return out
    call.lib = lib
    call.work = work
    call.rows = rows
    return call
