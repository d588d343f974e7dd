/* M X = B for many right-hand sides at many nodes: the solve of a tree's Jacobian
 * program (runtime/numerics/dynamics.py), compiled once at -O3 and linked into it.
 *
 * Each node's row of the program's outputs holds, from at_r, M's entries compactly
 * as loop.c's al_ltdl_solve holds them (row k: its diagonal, then its entries in the
 * columns col[start[k] + 1 ...] of its chain of parents), and from at_b the m x w
 * matrix B row after row, its rows in the factoring's order.  M = L^T D L is factored
 * in place without pivoting (Featherstone's LTDL), then B is overwritten by M^-1 B,
 * AL_BLOCK columns at a time: each row's block is summed in registers, from the rows
 * that update it (ustart, uk, uat: for row i, the rows k after it whose chain holds i,
 * from the last, and where L's entry is), which the compiler vectorizes.  Each entry
 * of B sees the operations of massmatrix.ltdl_columns (the rows k from the last, one
 * update each) in the same order: the same bits.  Returns 0, or 1 + the first node
 * where an entry of D is not positive and finite (M is then not positive definite:
 * singular where the model is). */
#include <math.h>

/* compiled twice where the loader can choose at run time (GCC's target clones on
 * glibc): with AVX2's four-wide operations on a processor that has them, and for any
 * x86-64; the same operations either way (no fused multiply-add), so the same bits */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__GLIBC__)
#define AL_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define AL_CLONES
#endif

#define AL_BLOCK 16     /* columns summed at once: four AVX2 registers */

/* rows of B from the last: each row less L's entries times the rows after it */
#define AL_DOWN(n) \
    for (k = m - 1; k >= 0; k--) { \
        double acc[AL_BLOCK], *bk = b + k * w + jb; \
        for (j = 0; j < (n); j++) acc[j] = bk[j]; \
        for (t = ustart[k]; t < ustart[k + 1]; t++) { \
            const double l = r[uat[t]], *bs = b + uk[t] * w + jb; \
            for (j = 0; j < (n); j++) acc[j] -= l * bs[j]; \
        } \
        for (j = 0; j < (n); j++) bk[j] = acc[j]; \
    }

/* rows from the first: each row by D^-1, less L's entries times the rows before it */
#define AL_UP(n) \
    for (k = 0; k < m; k++) { \
        const double *rk = r + start[k]; \
        double acc[AL_BLOCK], *bk = b + k * w + jb; \
        for (j = 0; j < (n); j++) acc[j] = bk[j] * rk[0]; \
        for (t = 1; t < start[k + 1] - start[k]; t++) { \
            const double l = rk[t], *bi = b + col[start[k] + t] * w + jb; \
            for (j = 0; j < (n); j++) acc[j] -= l * bi[j]; \
        } \
        for (j = 0; j < (n); j++) bk[j] = acc[j]; \
    }

/* M = L^T D L in place, the rows from the last, each row's L over its D entry, which is
 * inverted (D^-1 on each row's first place); -1 when an entry of D is not positive and
 * finite.  loop.c's one-right-hand-side solve factors with it too (the integration loop
 * links this source before its own). */
static int al_ltdl_factor(long m, double *r, const int *start, const int *col)
{
    long j, k, t;
    for (k = m - 1; k >= 0; k--) {
        double *rk = r + start[k], d = rk[0], inv;
        long len = start[k + 1] - start[k];
        if (!(d > 0.0) || d == INFINITY) return -1;
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
    return 0;
}

AL_CLONES
long autolev_ltdl_columns(long nodes, double *rows, long width, long at_r, long at_b,
                          long m, long w, const int *start, const int *col,
                          const int *ustart, const int *uk, const int *uat)
{
    long node, j, k, t, jb;
    for (node = 0; node < nodes; node++) {
        double *r = rows + node * width + at_r, *b = rows + node * width + at_b;
        if (al_ltdl_factor(m, r, start, col) != 0) return node + 1;
        for (jb = 0; jb + AL_BLOCK <= w; jb += AL_BLOCK) {
            AL_DOWN(AL_BLOCK)
            AL_UP(AL_BLOCK)
        }
        if (jb < w) {
            long rest = w - jb;
            AL_DOWN(rest)
            AL_UP(rest)
        }
    }
    return 0;
}
