/* autolev: the integration loop, compiled into the same library as a model's
 * right-hand side `autolev_rhs` (generated; see codegen.py), so that a whole run
 * -- every step, every right-hand-side call, the mass-matrix solve and the rows on
 * the print grid -- runs without Python.
 *
 * autolev_rhs(t, x, c, s, w, out) writes, for the n states, out[0..n) = the rates
 * known explicitly (0 where the rate is an acceleration solved from Kane's
 * equations), out[n..n+m*m) = the mass matrix M row by row and out[n+m*m..n+m*m+m)
 * = the forcing f; the m accelerations M^-1 f go to the state positions upos[].
 *
 * Three integrators, each the same step for step as its Python version (see
 * integrate.py): Autolev's Kutta-Merson on Autolev's INTEGSTP grid; the
 * Dormand-Prince 8(5,3) pair with its 7th-order dense output, with the error norm,
 * step-size control and first step of scipy's DOP853; and scipy's RK45 started afresh
 * over every INTEGSTP, as Autolev's Matlab programs call ode45 (the coefficient tables
 * are passed in as data by cloop.py).  The DOP853 run watches for
 * stiffness as Hairer's DOP853 does (h*|lambda| estimated from the last two stages
 * of each step) and stops with AL_STIFF when asked to.
 *
 * autolev_integrate() works in slices (at most `budget` right-hand-side calls per
 * call) so that the caller can show progress; everything that must survive between
 * slices lives in the caller's arrays `st` (scalars) and `work`.
 */
#include <math.h>
#include <string.h>

enum { AL_DONE = 0, AL_MORE = 1, AL_SINGULAR = 2, AL_SMALL_STEP = 3, AL_CUTS = 4,
       AL_NONFINITE = 5, AL_STIFF = 6 };

/* st[]: the persistent scalars (shared with cloop.py) */
enum { ST_T = 0,        /* time of the current state */
       ST_H,            /* step size carried to the next step (signed for KM) */
       ST_NUMCUTS,      /* Kutta-Merson: net halvings still allowed */
       ST_NFEV, ST_NSTEP, ST_NREJ,
       ST_ROW,          /* rows written so far (the row index to do next) */
       ST_STARTED,      /* DOP853: f at the current state is in work */
       ST_HAVE_STEP,    /* DOP853: a step was taken (its dense output is in work) */
       ST_TOLD, ST_HPREV,
       ST_FAIL_T, ST_FAIL_H,
       ST_IASTI, ST_NONSTI, ST_STIFF_T,
       ST_HLAMB,        /* the last h*|lambda| estimate */
       ST_KMROWS,       /* Kutta-Merson: rows written so far */
       ST_SIZE = 24 };

/* opts[] */
enum { OP_RTOL = 0, OP_ATOL, OP_MAXSTEP, OP_TBOUND, OP_STIFF_STOP, OP_BUDGET,
       OP_INTEGSTP,
       OP_FRESH };      /* Kutta-Merson: f at every step's start (Autolev 4.1's C) */

#define AL_NSTAGES 12
#define AL_NEXT 16
#define AL_NF 7

/* everything an evaluation needs; cloop.py fills the same layout (ctypes) */
typedef struct {
    int n, m;
    const int *upos;        /* where the m solved accelerations go in the state */
    const double *c, *s;    /* constants, specifieds */
    double *w, *out;        /* work and outputs of autolev_rhs */
    double *lu, *b;         /* m*m and m doubles for the solve */
    double *yfail;          /* n: the state at which the mass matrix was singular */
    double nfev;
    /* a symmetric mass matrix (massmatrix.MassStructure): the order its speeds are
     * factored in, where each compact row starts, the column (in that order) and the
     * place in M of each of its entries; NULL: solved by pivoting */
    const int *order, *start, *col, *gather;
} al_ctx;

/* M u' = f by Gaussian elimination with partial pivoting; -1 when a pivot is
 * exactly zero (LAPACK's dgetrf reports the same case).  Each pivot is inverted once
 * and multiplied by (divisions were most of the time of a small solve); system.py's
 * solve_mass_matrix does the same operations in the same order. */
static int al_lu_solve(int m, double *a, double *b)
{
    int i, j, k, p;
    double inv[64], *invd = m <= 64 ? inv : 0;
    for (k = 0; k < m; k++) {
        double amax = fabs(a[k * m + k]), r;
        p = k;
        for (i = k + 1; i < m; i++) {
            double v = fabs(a[i * m + k]);
            if (v > amax) { amax = v; p = i; }
        }
        if (amax == 0.0) return -1;
        if (p != k) {
            for (j = 0; j < m; j++) {
                double tmp = a[k * m + j]; a[k * m + j] = a[p * m + j]; a[p * m + j] = tmp;
            }
            { double tmp = b[k]; b[k] = b[p]; b[p] = tmp; }
        }
        r = 1.0 / a[k * m + k];
        if (invd) invd[k] = r;
        for (i = k + 1; i < m; i++) {
            double l = a[i * m + k] * r;
            if (l != 0.0) {
                for (j = k + 1; j < m; j++) a[i * m + j] -= l * a[k * m + j];
                b[i] -= l * b[k];
            }
        }
    }
    for (i = m - 1; i >= 0; i--) {
        double acc = b[i];
        for (j = i + 1; j < m; j++) acc -= a[i * m + j] * b[j];
        b[i] = acc * (invd ? invd[i] : 1.0 / a[i * m + i]);
    }
    return 0;
}

/* M u' = f for a symmetric M as M = L^T D L without pivoting, along each row's chain
 * of parents (Featherstone's LTDL).  Row k is held compactly in r + start[k]: its
 * entries in the columns col[start[k] ...] = k, parent[k], parent[parent[k]], ...
 * (the chain of an ancestor i of k is the tail of k's, so each update is one
 * contiguous loop); the rows become L's with D^-1 on their first places.  b is in the
 * factoring's order.  -1 when an entry of D is not positive and finite: M is then not
 * positive definite, and the caller solves it by pivoting.  massmatrix.py's
 * _solve_ltdl does the same operations on each entry in the same order. */
static int al_ltdl_solve(int m, double *r, double *b, const int *start, const int *col)
{
    int k, t;
    if (al_ltdl_factor(m, r, start, col) != 0) return -1;      /* ltdl.c's */
    for (k = m - 1; k >= 0; k--) {
        const double *rk = r + start[k], bk = b[k];
        const int *ck = col + start[k];
        int len = start[k + 1] - start[k];
        for (t = 1; t < len; t++) b[ck[t]] -= rk[t] * bk;
    }
    for (k = 0; k < m; k++) {
        const double *rk = r + start[k];
        const int *ck = col + start[k];
        int len = start[k + 1] - start[k];
        double acc = b[k] * rk[0];
        for (t = 1; t < len; t++) acc -= rk[t] * b[ck[t]];
        b[k] = acc;
    }
    return 0;
}

void autolev_rhs(const double *t, const double *x, const double *c, const double *s,
                 double *w, double *out);

/* the state derivative at (t, x); AL_SINGULAR when the mass matrix is */
static int al_f(al_ctx *ctx, double t, const double *x, double *xdot)
{
    int n = ctx->n, m = ctx->m, i;
    double tt = t;
    autolev_rhs(&tt, x, ctx->c, ctx->s, ctx->w, ctx->out);
    ctx->nfev += 1.0;
    memcpy(xdot, ctx->out, (size_t)n * sizeof(double));
    if (m == 0) return 0;
    if (m == 1) {
        double mm = ctx->out[n];
        if (mm == 0.0 || !isfinite(mm)) {
            memcpy(ctx->yfail, x, (size_t)n * sizeof(double));
            return AL_SINGULAR;
        }
        xdot[ctx->upos[0]] = ctx->out[n + 1] / mm;
        return 0;
    }
    if (ctx->order) {
        const int *o = ctx->order, *gather = ctx->gather, *start = ctx->start;
        const double *mm = ctx->out + n, *f = ctx->out + n + m * m;
        int nnz = start[m];
        for (i = 0; i < nnz; i++) ctx->lu[i] = mm[gather[i]];
        for (i = 0; i < m; i++) ctx->b[i] = f[o[i]];
        if (al_ltdl_solve(m, ctx->lu, ctx->b, start, ctx->col) == 0) {
            for (i = 0; i < m; i++) xdot[ctx->upos[o[i]]] = ctx->b[i];
            return 0;
        }
    }
    memcpy(ctx->lu, ctx->out + n, (size_t)m * m * sizeof(double));
    memcpy(ctx->b, ctx->out + n + m * m, (size_t)m * sizeof(double));
    if (al_lu_solve(m, ctx->lu, ctx->b) != 0) {
        memcpy(ctx->yfail, x, (size_t)n * sizeof(double));
        return AL_SINGULAR;
    }
    for (i = 0; i < m; i++) xdot[ctx->upos[i]] = ctx->b[i];
    return 0;
}

static int al_finite(int n, const double *y)
{
    int i;
    for (i = 0; i < n; i++) if (!isfinite(y[i])) return 0;
    return 1;
}

/* Hairer's stiffness test: h*|lambda| beyond the method's real stability boundary
 * (DOP853: 6.1; Kutta-Merson: 1.75, half its boundary -3.55, as its steps are INTEGSTP
 * over powers of 2 and the stable one lies in (1.77, 3.55]) in 15 accepted steps with
 * no run of 6 below it in between marks the equations stiff (from time t). */
static void al_stiff_count(double *st, double hlamb, double limit, double t)
{
    st[ST_HLAMB] = hlamb;
    if (hlamb > limit) {
        st[ST_NONSTI] = 0;
        st[ST_IASTI] += 1;
        if (st[ST_IASTI] >= 15 && st[ST_STIFF_T] != st[ST_STIFF_T]) st[ST_STIFF_T] = t;
    } else {
        st[ST_NONSTI] += 1;
        if (st[ST_NONSTI] >= 6) st[ST_IASTI] = 0;
    }
}

/* ---- Autolev's Kutta-Merson --------------------------------------------------- */

/* Advance y from t by exactly integstp (as KuttaMerson.advance in integrate.py).
 * work: 7 n doubles. */
static int al_km_advance(al_ctx *ctx, double *st, double *y, double t, double integstp,
                         double rtol, double atol, int fresh, double *work)
{
    int n = ctx->n, i, r;
    double *f0 = work, *f1 = work + n, *f2 = work + 2 * n, *y1 = work + 3 * n,
           *y2 = work + 4 * n, *fa = work + 5 * n, *ya = work + 6 * n;
    double lnum = 0, lden = 0;
    double h, tt, tfinal;
    if (st[ST_H] * integstp < 0) st[ST_H] = -st[ST_H];
    if (st[ST_H] == 0) st[ST_H] = integstp;
    h = st[ST_H];
    tt = t + h;
    tfinal = t + integstp;
    if ((r = al_f(ctx, tt - h, y, f0)) != 0) { st[ST_FAIL_T] = tt - h; return r; }
    for (;;) {
        double h2, h3, h6, h8;
        int bad = 0, dbl = 1;
        if (tt + h == tt) { st[ST_FAIL_T] = tt; st[ST_FAIL_H] = h; return AL_SMALL_STEP; }
        h2 = h * 0.5; h3 = h / 3.0; h6 = h / 6.0; h8 = h * 0.125;
        for (i = 0; i < n; i++) y1[i] = y[i] + h3 * f0[i];
        if ((r = al_f(ctx, tt - 2.0 * h3, y1, f1)) != 0) { st[ST_FAIL_T] = tt - 2.0 * h3; return r; }
        memcpy(fa, f1, (size_t)n * sizeof(double));
        memcpy(ya, y1, (size_t)n * sizeof(double));
        for (i = 0; i < n; i++) y1[i] = y[i] + h6 * (f0[i] + f1[i]);
        if ((r = al_f(ctx, tt - 2.0 * h3, y1, f1)) != 0) { st[ST_FAIL_T] = tt - 2.0 * h3; return r; }
        /* stages 2 and 3 are at the same time: |f1 - fa| / |y1 - ya| ~ |lambda| */
        lnum = 0; lden = 0;
        for (i = 0; i < n; i++) {
            double a = f1[i] - fa[i], b = y1[i] - ya[i];
            lnum += a * a; lden += b * b;
        }
        for (i = 0; i < n; i++) y1[i] = y[i] + h8 * (f0[i] + 3.0 * f1[i]);
        if ((r = al_f(ctx, tt - h2, y1, f2)) != 0) { st[ST_FAIL_T] = tt - h2; return r; }
        for (i = 0; i < n; i++) y1[i] = y[i] + h2 * (f0[i] - 3.0 * f1[i] + 4.0 * f2[i]);
        if ((r = al_f(ctx, tt, y1, f1)) != 0) { st[ST_FAIL_T] = tt; return r; }
        for (i = 0; i < n; i++) y2[i] = y[i] + h6 * (f0[i] + 4.0 * f2[i] + f1[i]);
        for (i = 0; i < n; i++) {
            double error = fabs(y1[i] - y2[i]) * 0.2;
            double test = fabs(y1[i]) * rtol;
            if (error >= test && error >= atol) bad = 1;
            if (64.0 * error > test && 64.0 * error > atol) dbl = 0;
        }
        if (bad) {
            st[ST_H] = h = h2;
            tt = tt - h2;
            st[ST_NUMCUTS] -= 1;
            st[ST_NREJ] += 1;
            if (st[ST_NUMCUTS] >= 0) continue;
            st[ST_FAIL_T] = tt - h;
            return AL_CUTS;
        }
        if (!al_finite(n, y2)) { st[ST_FAIL_T] = tt - h; st[ST_FAIL_H] = h; return AL_NONFINITE; }
        st[ST_NSTEP] += 1;
        if (lden > 0) al_stiff_count(st, fabs(h) * sqrt(lnum / lden), 1.75, tt);
        memcpy(y, y2, (size_t)n * sizeof(double));
        if (dbl && fabs(h + h) <= fabs(integstp) && fabs(tt + h + h) <= fabs(tfinal)) {
            st[ST_H] = h = h + h;
            st[ST_NUMCUTS] += 1;
        }
        if (tt == tfinal) return 0;
        tt = tt + h;
        if ((h > 0 && tt > tfinal - 0.1 * h) || (h < 0 && tt < tfinal - 0.1 * h)) {
            h = tfinal - (tt - h);
            tt = tfinal;
        }
        if (fresh) {
            if ((r = al_f(ctx, tt - h, y, f0)) != 0) { st[ST_FAIL_T] = tt - h; return r; }
        } else {
            memcpy(f0, f1, (size_t)n * sizeof(double));
        }
    }
}

/* ---- DOP853 ------------------------------------------------------------------- */

static double al_rms(int n, const double *v)
{
    double s = 0;
    int i;
    for (i = 0; i < n; i++) s += v[i] * v[i];
    return sqrt(s / n);
}

/* the first step of scipy's solvers (Hairer, Norsett and Wanner, II.4) for a method
 * whose error estimate has order `order`, from f0 = f(t, y) to t_bound; -1 on a
 * failing evaluation (st[ST_FAIL_T] set) */
static double al_first_step(al_ctx *ctx, double *st, double t, const double *y,
                            const double *f0, double t_bound, double max_step, double rtol,
                            double atol, int order, double *scale, double *tmp,
                            double *f1, int *status)
{
    int n = ctx->n, i, r;
    double d0, d1, d2, h0, h1, h, len = fabs(t_bound - t), dir = t_bound >= t ? 1.0 : -1.0;
    *status = 0;
    if (len == 0.0) return 0.0;
    for (i = 0; i < n; i++) scale[i] = atol + fabs(y[i]) * rtol;
    for (i = 0; i < n; i++) tmp[i] = y[i] / scale[i];
    d0 = al_rms(n, tmp);
    for (i = 0; i < n; i++) tmp[i] = f0[i] / scale[i];
    d1 = al_rms(n, tmp);
    h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    if (h0 > len) h0 = len;
    for (i = 0; i < n; i++) tmp[i] = y[i] + h0 * dir * f0[i];
    if ((r = al_f(ctx, t + h0 * dir, tmp, f1)) != 0) {
        st[ST_FAIL_T] = t; *status = r; return -1.0;
    }
    for (i = 0; i < n; i++) tmp[i] = (f1[i] - f0[i]) / scale[i];
    d2 = al_rms(n, tmp) / h0;
    if (d1 <= 1e-15 && d2 <= 1e-15) h1 = 1e-6 > h0 * 1e-3 ? 1e-6 : h0 * 1e-3;
    else h1 = pow(0.01 / (d1 > d2 ? d1 : d2), 1.0 / (order + 1));
    h = 100 * h0;
    if (h1 < h) h = h1;
    if (len < h) h = len;
    if (max_step < h) h = max_step;
    return h;
}

/* scipy's change of step after the error norm `err` (RungeKutta._step_impl, for an
 * error estimate of order `order`): accepted (err < 1), 0.9 err^(-1/(order+1)), at
 * most 10 and not above 1 right after a rejection; rejected, at least 0.2 (Python's
 * max(0.2, nan): a NaN error shrinks the step) */
static double al_step_factor(double err, int order, int rejected)
{
    double factor = err == 0 ? 10.0 : 0.9 * pow(err, -1.0 / (order + 1));
    if (err < 1) {
        if (factor > 10.0) factor = 10.0;
        if (rejected && factor > 1) factor = 1;
        return factor;
    }
    return factor > 0.2 ? factor : 0.2;
}

/* work layout for DOP853 (n = states):
 *   K[16][n] | y_new n | f_cur n | y_old n | ystage n | F[7][n] | tmp n | scale n */
#define DK(s) (work + (size_t)(s) * n)

static int al_dop_stages(al_ctx *ctx, const double *A, const double *C, double t,
                         const double *y, double h, double *work, int from, int to,
                         double *ytmp)
{
    int n = ctx->n, s, j, i, r;
    for (s = from; s < to; s++) {
        for (i = 0; i < n; i++) {
            double acc = 0;
            for (j = 0; j < s; j++) {
                double a = A[s * AL_NEXT + j];
                if (a != 0.0) acc += DK(j)[i] * a;
            }
            ytmp[i] = y[i] + acc * h;
        }
        if ((r = al_f(ctx, t + C[s] * h, ytmp, DK(s))) != 0) {
            (void)r;
            return r;
        }
    }
    return 0;
}

static int al_dop_run(al_ctx *ctx, double *st, const double *opts, double *y,
                      int ntimes, const double *times, double *rows, double *work,
                      const double *A, const double *B, const double *C,
                      const double *E3, const double *E5, const double *D)
{
    int n = ctx->n, i, s, r;
    double rtol = opts[OP_RTOL], atol = opts[OP_ATOL], max_step = opts[OP_MAXSTEP];
    double t_bound = opts[OP_TBOUND];
    double budget = opts[OP_BUDGET], start = ctx->nfev;
    double dir = t_bound >= st[ST_T] ? 1.0 : -1.0;
    double *ynew = DK(AL_NEXT), *fcur = ynew + n, *yold = fcur + n, *ystage = yold + n,
           *F = ystage + n, *tmp = F + (size_t)AL_NF * n, *scale = tmp + n;
    int k = (int)st[ST_ROW];

    if (!st[ST_STARTED]) {
        /* f at the start, and scipy's first step */
        if ((r = al_f(ctx, st[ST_T], y, fcur)) != 0) { st[ST_FAIL_T] = st[ST_T]; return r; }
        if (!al_finite(n, fcur)) { st[ST_FAIL_T] = st[ST_T]; return AL_NONFINITE; }
        st[ST_H] = al_first_step(ctx, st, st[ST_T], y, fcur, t_bound, max_step, rtol, atol,
                                 7, scale, tmp, DK(0), &r);
        if (r != 0) return r;
        st[ST_STARTED] = 1;
    }

    for (;;) {
        /* rows that the last step covers */
        if (st[ST_HAVE_STEP]) {
            double told = st[ST_TOLD], hp = st[ST_HPREV];
            while (k < ntimes && (times[k] - st[ST_T]) * dir <= 0) {
                double *row = rows + (size_t)k * n;
                if (times[k] == st[ST_T]) {
                    memcpy(row, y, (size_t)n * sizeof(double));
                } else {
                    double x = (times[k] - told) / hp;
                    int j;
                    for (i = 0; i < n; i++) row[i] = 0.0;
                    for (j = 0; j < AL_NF; j++) {
                        const double *fj = F + (size_t)(AL_NF - 1 - j) * n;
                        double mult = (j % 2 == 0) ? x : 1.0 - x;
                        for (i = 0; i < n; i++) row[i] = (row[i] + fj[i]) * mult;
                    }
                    for (i = 0; i < n; i++) row[i] += yold[i];
                }
                k++;
            }
            st[ST_ROW] = k;
        }
        if (k >= ntimes) return AL_DONE;
        if (st[ST_T] == t_bound) {        /* t_bound reached exactly: the rest coincide */
            while (k < ntimes) {
                memcpy(rows + (size_t)k * n, y, (size_t)n * sizeof(double));
                k++;
            }
            st[ST_ROW] = k;
            return AL_DONE;
        }
        if (opts[OP_STIFF_STOP] != 0 && st[ST_STIFF_T] == st[ST_STIFF_T]) return AL_STIFF;
        if (ctx->nfev - start >= budget) return AL_MORE;

        /* one step, as scipy's RungeKutta._step_impl */
        {
            double t = st[ST_T];
            double min_step = 10 * fabs(nextafter(t, dir * INFINITY) - t);
            double h_abs = st[ST_H], h, t_new, err;
            int rejected = 0;
            if (h_abs > max_step) h_abs = max_step;
            else if (h_abs < min_step) h_abs = min_step;
            for (;;) {
                double e5 = 0, e3 = 0;
                if (h_abs < min_step) {
                    st[ST_FAIL_T] = t; st[ST_FAIL_H] = h_abs; return AL_SMALL_STEP;
                }
                h = h_abs * dir;
                t_new = t + h;
                if (dir * (t_new - t_bound) > 0) t_new = t_bound;
                h = t_new - t;
                h_abs = fabs(h);
                memcpy(DK(0), fcur, (size_t)n * sizeof(double));
                if ((r = al_dop_stages(ctx, A, C, t, y, h, work, 1, AL_NSTAGES, ystage)) != 0) {
                    st[ST_FAIL_T] = t; return r;
                }
                for (i = 0; i < n; i++) {
                    double acc = 0;
                    for (s = 0; s < AL_NSTAGES; s++) acc += DK(s)[i] * B[s];
                    ynew[i] = y[i] + h * acc;
                }
                if ((r = al_f(ctx, t + h, ynew, DK(AL_NSTAGES))) != 0) {
                    st[ST_FAIL_T] = t; return r;
                }
                for (i = 0; i < n; i++) {
                    double a = fabs(y[i]), b = fabs(ynew[i]);
                    double sc = atol + (a > b ? a : b) * rtol;
                    double r5 = 0, r3 = 0;
                    for (s = 0; s <= AL_NSTAGES; s++) {
                        r5 += DK(s)[i] * E5[s];
                        r3 += DK(s)[i] * E3[s];
                    }
                    r5 /= sc; r3 /= sc;
                    e5 += r5 * r5; e3 += r3 * r3;
                }
                if (e5 == 0 && e3 == 0) err = 0;
                else err = h_abs * e5 / sqrt((e5 + 0.01 * e3) * n);
                if (!(err == err)) {                     /* NaN: not finite */
                    st[ST_FAIL_T] = t; return AL_NONFINITE;
                }
                h_abs *= al_step_factor(err, 7, rejected);
                if (err < 1) break;
                rejected = 1;
                st[ST_NREJ] += 1;
            }
            if (!al_finite(n, ynew)) { st[ST_FAIL_T] = t; return AL_NONFINITE; }
            st[ST_NSTEP] += 1;
            /* stiffness (Hairer's DOP853): the last stage and f at the new state are at
             * the same time, so |f(ynew) - f(ystage)| / |ynew - ystage| ~ |lambda| */
            {
                double num = 0, den = 0;
                for (i = 0; i < n; i++) {
                    double a = DK(AL_NSTAGES)[i] - DK(AL_NSTAGES - 1)[i];
                    double b = ynew[i] - ystage[i];
                    num += a * a; den += b * b;
                }
                if (den > 0) al_stiff_count(st, h_abs * sqrt(num / den), 6.1, t_new);
            }
            /* dense output of the step (scipy's DOP853 interpolant) */
            memcpy(yold, y, (size_t)n * sizeof(double));
            if (k < ntimes && (times[k] - t_new) * dir < 0) {
                if ((r = al_dop_stages(ctx, A, C, t, yold, h, work, AL_NSTAGES + 1, AL_NEXT,
                                       tmp)) != 0) {
                    st[ST_FAIL_T] = t; return r;
                }
                for (i = 0; i < n; i++) {
                    double dy = ynew[i] - yold[i];
                    F[i] = dy;
                    F[n + i] = h * DK(0)[i] - dy;
                    F[2 * n + i] = 2 * dy - h * (DK(AL_NSTAGES)[i] + DK(0)[i]);
                }
                for (s = 0; s < AL_NF - 3; s++) {
                    for (i = 0; i < n; i++) {
                        double acc = 0;
                        int j;
                        for (j = 0; j < AL_NEXT; j++) {
                            double d = D[s * AL_NEXT + j];
                            if (d != 0.0) acc += d * DK(j)[i];
                        }
                        F[(size_t)(3 + s) * n + i] = h * acc;
                    }
                }
            }
            memcpy(fcur, DK(AL_NSTAGES), (size_t)n * sizeof(double));
            memcpy(y, ynew, (size_t)n * sizeof(double));
            st[ST_TOLD] = t;
            st[ST_HPREV] = h;
            st[ST_T] = t_new;
            st[ST_H] = h_abs;
            st[ST_HAVE_STEP] = 1;
        }
    }
}

/* ---- RK45 afresh over every INTEGSTP (Autolev's Matlab programs) --------------- */

/* scipy's RK45 from (st[ST_T], y) to t_bound, started afresh (as ode45 over one
 * INTEGSTP in Autolev's Matlab loop): f at the start, scipy's first step, then its
 * steps (RungeKutta._step_impl) until t_bound.  work: 11 n doubles; tab: A (6 x 6),
 * B (6), C (6), E (7).  On a failure y is the last accepted state, st[ST_FAIL_T] the
 * time of that state and st[ST_FAIL_H] the step tried from it. */
static int al_rk45_interval(al_ctx *ctx, double *st, const double *opts, double *y,
                            double t_bound, double *work, const double *tab)
{
    int n = ctx->n, i, s, j, r;
    const double *A = tab, *B = A + 36, *C = B + 6, *E = C + 6;
    double rtol = opts[OP_RTOL], atol = opts[OP_ATOL], max_step = opts[OP_MAXSTEP];
    double t = st[ST_T], dir = t_bound >= t ? 1.0 : -1.0, h_abs;
    double *K = work, *ynew = K + 7 * (size_t)n, *ytmp = ynew + n, *scale = ytmp + n,
           *tmp = scale + n;
    if ((r = al_f(ctx, t, y, K)) != 0) { st[ST_FAIL_T] = t; return r; }
    h_abs = al_first_step(ctx, st, t, y, K, t_bound, max_step, rtol, atol, 4, scale, tmp,
                          K + n, &r);
    if (r != 0) return r;
    while (t != t_bound) {
        double min_step = 10 * fabs(nextafter(t, dir * INFINITY) - t);
        double h, t_new, err;
        int rejected = 0;
        if (h_abs > max_step) h_abs = max_step;
        else if (h_abs < min_step) h_abs = min_step;
        for (;;) {
            double e = 0;
            if (h_abs < min_step) {
                st[ST_FAIL_T] = t; st[ST_FAIL_H] = h_abs; return AL_SMALL_STEP;
            }
            h = h_abs * dir;
            t_new = t + h;
            if (dir * (t_new - t_bound) > 0) t_new = t_bound;
            h = t_new - t;
            h_abs = fabs(h);
            for (s = 1; s < 6; s++) {
                for (i = 0; i < n; i++) {
                    double acc = 0;
                    for (j = 0; j < s; j++) acc += K[(size_t)j * n + i] * A[s * 6 + j];
                    ytmp[i] = y[i] + acc * h;
                }
                if ((r = al_f(ctx, t + C[s] * h, ytmp, K + (size_t)s * n)) != 0) {
                    st[ST_FAIL_T] = t; st[ST_FAIL_H] = h; return r;
                }
            }
            for (i = 0; i < n; i++) {
                double acc = 0;
                for (s = 0; s < 6; s++) acc += K[(size_t)s * n + i] * B[s];
                ynew[i] = y[i] + h * acc;
            }
            if ((r = al_f(ctx, t + h, ynew, K + 6 * (size_t)n)) != 0) {
                st[ST_FAIL_T] = t; st[ST_FAIL_H] = h; return r;
            }
            for (i = 0; i < n; i++) {
                double a = fabs(y[i]), b = fabs(ynew[i]), acc = 0, q;
                for (s = 0; s < 7; s++) acc += K[(size_t)s * n + i] * E[s];
                q = acc * h / (atol + (a > b ? a : b) * rtol);
                e += q * q;
            }
            err = sqrt(e / n);
            h_abs *= al_step_factor(err, 4, rejected);
            if (err < 1) break;
            rejected = 1;
            st[ST_NREJ] += 1;
        }
        st[ST_NSTEP] += 1;
        if (!al_finite(n, ynew)) { st[ST_FAIL_T] = t; st[ST_FAIL_H] = h; return AL_NONFINITE; }
        memcpy(y, ynew, (size_t)n * sizeof(double));
        memcpy(K, K + 6 * (size_t)n, (size_t)n * sizeof(double));
        t = t_new;
    }
    return 0;
}

/* Autolev's loop: steps[k] is T after step k (accumulated as Autolev did), printed[k]
 * whether a row is printed there.  Each step is Kutta-Merson's (method 0) or RK45's
 * started afresh (method 2, tab its tableau).  Rows go to rows[] (one per printed
 * step). */
static int al_stepped_run(al_ctx *ctx, double *st, const double *opts, double *y,
                          int nsteps, const double *steps, const int *printed,
                          double *rows, double *rtimes, double *work, int method,
                          const double *tab)
{
    int n = ctx->n, r;
    double budget = opts[OP_BUDGET], start = ctx->nfev;
    int k = (int)st[ST_ROW];           /* here: the step index to do next */
    while (k < nsteps) {
        r = method == 0
            ? al_km_advance(ctx, st, y, st[ST_T], opts[OP_INTEGSTP], opts[OP_RTOL],
                            opts[OP_ATOL], opts[OP_FRESH] != 0, work)
            : al_rk45_interval(ctx, st, opts, y, steps[k], work, tab);
        if (r != 0) return r;
        st[ST_T] = steps[k];
        if (printed[k]) {
            int j = (int)st[ST_KMROWS];
            memcpy(rows + (size_t)j * n, y, (size_t)n * sizeof(double));
            rtimes[j] = st[ST_T];
            st[ST_KMROWS] = j + 1;
        }
        k++;
        st[ST_ROW] = k;
        if (ctx->nfev - start >= budget && k < nsteps) return AL_MORE;
    }
    return AL_DONE;
}

/* method 0: Kutta-Merson over steps[]/printed[] (ntimes steps); 1: DOP853 at the
 * print times times[]; 2: RK45 afresh over each of steps[] (coef: the method's
 * tableau).  Returns AL_DONE, AL_MORE (call again), or a failure
 * (st[ST_FAIL_T] says where; y holds the last accepted state, st[ST_T] its time). */
int autolev_integrate(al_ctx *ctx, int method, double *y, double *st, const double *opts,
                      int ntimes, const double *times, const int *printed,
                      double *rows, double *rtimes, double *work, const double *coef)
{
    int r;
    ctx->nfev = st[ST_NFEV];
    if (method == 0 || method == 2) {
        r = al_stepped_run(ctx, st, opts, y, ntimes, times, printed, rows, rtimes, work,
                           method, coef);
    } else {
        const double *A = coef, *B = A + AL_NEXT * AL_NEXT, *C = B + AL_NSTAGES,
                     *E3 = C + AL_NEXT, *E5 = E3 + AL_NSTAGES + 1,
                     *D = E5 + AL_NSTAGES + 1;
        r = al_dop_run(ctx, st, opts, y, ntimes, times, rows, work, A, B, C, E3, E5, D);
    }
    st[ST_NFEV] = ctx->nfev;
    return r;
}

/* one evaluation of the state derivative: 0, or AL_SINGULAR */
int autolev_derivatives(al_ctx *ctx, double t, const double *x, double *xdot)
{
    return al_f(ctx, t, x, xdot);
}
