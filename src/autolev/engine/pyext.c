/* autolev: a CPython entry point for the right-hand side, compiled into the same
 * library as loop.c when Python's and numpy's headers are there (cloop.py).  A
 * ctypes call costs a few microseconds of argument conversion; this costs a fraction
 * of one, which is what scipy's integrators, calling back into Python at every
 * stage, see.
 *
 * rhs(ctx_address, t, x) -> a new array x' at (t, x), or None when the mass matrix is
 * singular.  x: a C-contiguous float64 buffer of the state's length (anything else is
 * a TypeError or ValueError, and cloop.py goes through ctypes instead). */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>

static PyObject *al_py_rhs(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    al_ctx *ctx;
    double t;
    Py_buffer xb;
    npy_intp dims[1];
    PyObject *out;
    int r;
    (void)self;
    if (nargs != 3) {
        PyErr_SetString(PyExc_TypeError, "rhs(ctx, t, x)");
        return NULL;
    }
    ctx = (al_ctx *)PyLong_AsVoidPtr(args[0]);
    if (ctx == NULL && PyErr_Occurred()) return NULL;
    t = PyFloat_AsDouble(args[1]);
    if (t == -1.0 && PyErr_Occurred()) return NULL;
    if (PyObject_GetBuffer(args[2], &xb, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) != 0)
        return NULL;
    if (xb.itemsize != 8 || xb.format == NULL || strcmp(xb.format, "d") != 0 ||
        xb.len != (Py_ssize_t)ctx->n * 8) {
        PyBuffer_Release(&xb);
        PyErr_SetString(PyExc_TypeError, "expected a float64 array of the state's length");
        return NULL;
    }
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
