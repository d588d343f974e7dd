"""Rows of Autolev's output files as text, many at once: in C where a C compiler is
found (the "%- 14.6E" of Autolev's own programs, its digits from a scaled double and
printf's where that cannot settle the rounding: a quarter of Python's time on a long
run's rows), else by Python's %, which writes the same characters."""
from __future__ import annotations

import ctypes
import functools

import numpy as np

from .clibrary import CompileError, build_shared_library, compiler
from .numbers import row

# a finite double takes at most 14 characters in "%- 14.6E" (-1.797693E+308), as do
# INF and NAN padded: 15 with the space before it
VALUE_WIDTH = 15

ROWS_SOURCE = r"""
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double POW10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10,
    1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

/* " %- 14.6E" of v into p; returns the number of characters.  The seven digits come
   from v scaled by an exact power of ten (one rounding, at most 1.2e-9 off in the
   units of the last digit); where that cannot settle the rounding (near a half, or
   a power of ten out of the exact range) printf writes it.  A NaN is written without
   its sign, as Python's % writes it. */
static int format_value(char *p, double v)
{
    double a = fabs(v);
    if (a == 0.0) {
        memcpy(p, signbit(v) ? " -0.000000E+00 " : "  0.000000E+00 ", 15);
        return 15;
    }
    if (!isfinite(a))
        return sprintf(p, " %- 14.6E", isnan(v) ? NAN : v);
    int e = (int)floor(log10(a));
    int k = 6 - e;
    if (k < -22 || k > 22)
        return sprintf(p, " %- 14.6E", v);
    double s = k >= 0 ? a * POW10[k] : a / POW10[-k];
    double whole = floor(s);
    double frac = s - whole;
    if (s < 1e6 || s >= 1e7 - 1.0 || fabs(frac - 0.5) < 1e-8)
        return sprintf(p, " %- 14.6E", v);
    long n = (long)whole + (frac > 0.5);
    char *q = p;
    *q++ = ' ';
    *q++ = v < 0 ? '-' : ' ';
    char digits[7];
    for (int i = 6; i >= 0; i--) {
        digits[i] = (char)('0' + n % 10);
        n /= 10;
    }
    *q++ = digits[0];
    *q++ = '.';
    for (int i = 1; i < 7; i++)
        *q++ = digits[i];
    *q++ = 'E';
    *q++ = e < 0 ? '-' : '+';
    int x = e < 0 ? -e : e;
    if (x >= 100)
        *q++ = (char)('0' + x / 100);
    *q++ = (char)('0' + (x / 10) % 10);
    *q++ = (char)('0' + x % 10);
    while (q - p < 15)
        *q++ = ' ';
    return (int)(q - p);
}

/* rows x cols values (C order) as the lines of an output file.  Returns the number of
   characters. */
long al_format_rows(const double *values, long rows, long cols, char *out)
{
    char *p = out;
    for (long i = 0; i < rows; i++) {
        for (long j = 0; j < cols; j++)
            p += format_value(p, values[i * cols + j]);
        *p++ = '\n';
    }
    return (long)(p - out);
}
"""


@functools.cache
def _formatter():
    """The C function, or None without a compiler (or when it fails to build)."""
    if compiler() is None:
        return None
    try:
        library = ctypes.CDLL(str(build_shared_library(ROWS_SOURCE)))
    except (CompileError, OSError):
        return None
    fn = library.al_format_rows
    fn.argtypes = [ctypes.c_void_p, ctypes.c_long, ctypes.c_long, ctypes.c_char_p]
    fn.restype = ctypes.c_long
    return fn


def prepare() -> None:
    """Build the formatter now (cached for every model): the compiled loop's rows use
    it, and a cold run that began in Python did not."""
    _formatter()


def python_rows_text(block) -> str:
    """The same text by the writer of a row at a time (numbers.row, Python's %)."""
    return "".join(row(r) for r in block)


def rows_text(block: np.ndarray) -> str:
    """The lines of an output file for `block` (print times x columns)."""
    values = np.ascontiguousarray(block, dtype=np.float64)
    rows, cols = values.shape
    fn = _formatter()
    if fn is None or rows == 0:
        return python_rows_text(values.tolist())
    out = ctypes.create_string_buffer(rows * (cols * VALUE_WIDTH + 1) + 1)
    length = fn(values.ctypes.data, rows, cols, out)
    return out.raw[:length].decode("ascii")
