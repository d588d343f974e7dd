/* autolev: a CPython entry point for the right-hand side, compiled into the same
 * library as loop.c when Python's headers are there (cloop.py).  A ctypes call costs
 * a few microseconds of argument conversion; this costs a fraction of one, which is
 * what scipy's integrators, calling back into Python at every stage, see.
 *
 * derivatives(ctx_address, t, x, out) -> status: out[:] = x' at (t, x); 0, or
 * AL_SINGULAR.  x and out: C-contiguous float64 buffers of the state's length.
 * rhs(ctx_address, t, x) -> a new array x', or None when the mass matrix is singular
 * (the array made here: one Python call less than numpy.empty + derivatives). */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>

static int al_buffer(PyObject *o, Py_buffer *b, int writable, Py_ssize_t n)
{
    if (PyObject_GetBuffer(o, b, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT |
                                   (writable ? PyBUF_WRITABLE : 0)) != 0)
        return -1;
    if (b->itemsize != 8 || b->format == NULL || strcmp(b->format, "d") != 0 ||
        b->len != n * 8) {
        PyBuffer_Release(b);
        PyErr_SetString(PyExc_TypeError, "expected a float64 array of the state's length");
        return -1;
    }
    return 0;
}

/* the arguments both entry points share: (ctx, t, x, ...); 0, or -1 with an error */
static int al_args(PyObject *const *args, Py_ssize_t nargs, Py_ssize_t want,
                   const char *usage, al_ctx **ctx, double *t, Py_buffer *xb)
{
    if (nargs != want) {
        PyErr_SetString(PyExc_TypeError, usage);
        return -1;
    }
    *ctx = (al_ctx *)PyLong_AsVoidPtr(args[0]);
    if (*ctx == NULL && PyErr_Occurred()) return -1;
    *t = PyFloat_AsDouble(args[1]);
    if (*t == -1.0 && PyErr_Occurred()) return -1;
    return al_buffer(args[2], xb, 0, (*ctx)->n);
}

static PyObject *al_py_derivatives(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    al_ctx *ctx;
    double t;
    Py_buffer xb, ob;
    int r;
    (void)self;
    if (al_args(args, nargs, 4, "derivatives(ctx, t, x, out)", &ctx, &t, &xb) != 0)
        return NULL;
    if (al_buffer(args[3], &ob, 1, ctx->n) != 0) {
        PyBuffer_Release(&xb);
        return NULL;
    }
    r = al_f(ctx, t, (const double *)xb.buf, (double *)ob.buf);
    PyBuffer_Release(&xb);
    PyBuffer_Release(&ob);
    return PyLong_FromLong(r);
}

static PyObject *al_py_rhs(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    al_ctx *ctx;
    double t;
    Py_buffer xb;
    npy_intp dims[1];
    PyObject *out;
    int r;
    (void)self;
    if (al_args(args, nargs, 3, "rhs(ctx, t, x)", &ctx, &t, &xb) != 0)
        return NULL;
    dims[0] = ctx->n;
    out = PyArray_SimpleNew(1, dims, NPY_DOUBLE);
    if (out == NULL) {
        PyBuffer_Release(&xb);
        return NULL;
    }
    r = al_f(ctx, t, (const double *)xb.buf,
             (double *)PyArray_DATA((PyArrayObject *)out));
    PyBuffer_Release(&xb);
    if (r != 0) {
        Py_DECREF(out);
        Py_RETURN_NONE;
    }
    return out;
}

static PyMethodDef al_methods[] = {
    {"rhs", (PyCFunction)(void (*)(void))al_py_rhs, METH_FASTCALL,
     "rhs(ctx, t, x) -> x' (a new array), or None when the mass matrix is singular"},
    {"derivatives", (PyCFunction)(void (*)(void))al_py_derivatives, METH_FASTCALL,
     "derivatives(ctx, t, x, out) -> status"},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef al_module = {
    PyModuleDef_HEAD_INIT, "_autolev_rhs", NULL, -1, al_methods, NULL, NULL, NULL, NULL
};

PyMODINIT_FUNC PyInit__autolev_rhs(void)
{
    import_array();
    return PyModule_Create(&al_module);
}
