/* M X = B for many right-hand sides at many nodes: the solve of a tree's Jacobian
 * program (runtime/numerics/dynamics.py), compiled once at -O3 and linked into it.
 *
 * Each node's row of the program's outputs holds, from at_r, M's entries compactly
 * as loop.c's al_ltdl_solve holds them (row k: its diagonal, then its entries in the
 * columns col[start[k] + 1 ...] of its chain of parents), and from at_b the m x w
 * matrix B row after row, its rows in the factoring's order.  M = L^T D L is factored
 * in place without pivoting (Featherstone's LTDL), then B is overwritten by M^-1 B;
 * each update of B is one row times a number, over the w columns, which the compiler
 * vectorizes.  massmatrix.ltdl_columns does the same operations on each entry in the
 * same order.  Returns 0, or 1 + the first node where an entry of D is not positive
 * and finite (M is then not positive definite: singular where the model is). */
#include <math.h>

/* compiled twice where the loader can choose at run time (GCC's target clones on
 * glibc): with AVX2's four-wide operations on a processor that has them, and for any
 * x86-64; the same operations either way (no fused multiply-add), so the same bits */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__GLIBC__)
#define AL_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define AL_CLONES
#endif

AL_CLONES
long autolev_ltdl_columns(long nodes, double *rows, long width, long at_r, long at_b,
                          long m, long w, const int *start, const int *col)
{
    long node, j, k, t;
    for (node = 0; node < nodes; node++) {
        double *r = rows + node * width + at_r, *b = rows + node * width + at_b;
        for (k = m - 1; k >= 0; k--) {
            double *rk = r + start[k], d = rk[0], inv;
            long len = start[k + 1] - start[k];
            if (!(d > 0.0) || d == INFINITY) return node + 1;
            inv = 1.0 / d;
            for (t = 1; t < len; t++) {
                long i = col[start[k] + t], n = start[i + 1] - start[i];
                double *ri = r + start[i], l = rk[t] * inv;
                const double *tail = rk + t;
                for (j = 0; j < n; j++) ri[j] -= l * tail[j];
                rk[t] = l;
            }
            rk[0] = inv;
        }
        for (k = m - 1; k >= 0; k--) {          /* L^T Y = B */
            const double *rk = r + start[k], *bk = b + k * w;
            long len = start[k + 1] - start[k];
            for (t = 1; t < len; t++) {
                double l = rk[t], *bi = b + col[start[k] + t] * w;
                for (j = 0; j < w; j++) bi[j] -= l * bk[j];
            }
        }
        for (k = 0; k < m; k++) {               /* D Z = Y and L X = Z, row by row */
            const double *rk = r + start[k];
            double *bk = b + k * w, inv = rk[0];
            long len = start[k + 1] - start[k];
            for (j = 0; j < w; j++) bk[j] *= inv;
            for (t = 1; t < len; t++) {
                double l = rk[t];
                const double *bi = b + col[start[k] + t] * w;
                for (j = 0; j < w; j++) bk[j] -= l * bi[j];
            }
        }
    }
    return 0;
}
