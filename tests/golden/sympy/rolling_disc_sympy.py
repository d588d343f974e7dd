"""rolling_disc: the model in sympy.physics.mechanics, written by autolev from
rolling_disc.al (CODE DYNAMICS rolling_disc.c).

Level: mechanics.  Frames, points, particles and rigid bodies, loads and the
kinematical differential equations as the model gives them; sympy's KanesMethod
forms the equations of motion when the script is imported.  Importing defines
`kane` (its equations formed), `constants`, `initial_conditions` and `specified`;
`python THIS.py [OUT.csv]` integrates from TINITIAL to TFINAL with scipy
(DOP853, RELERR and ABSERR) and writes the OUTPUT columns as CSV.
"""
import sys

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me
from scipy.integrate import solve_ivp

t = me.dynamicsymbols._t

# generalized coordinates and speeds: functions of time
Q1 = me.dynamicsymbols('Q1')
Q2 = me.dynamicsymbols('Q2')
Q3 = me.dynamicsymbols('Q3')
Q4 = me.dynamicsymbols('Q4')
Q5 = me.dynamicsymbols('Q5')
U1 = me.dynamicsymbols('U1')
U2 = me.dynamicsymbols('U2')
U3 = me.dynamicsymbols('U3')
U4 = me.dynamicsymbols('U4')
U5 = me.dynamicsymbols('U5')

# constants
R = sm.Symbol('R')
M = sm.Symbol('M')
G = sm.Symbol('G')

# reference frames, oriented as the model orients them, with its angular velocities
N = me.ReferenceFrame('N')
# rolling_disc.al:15: SIMPROT(N, A, 3, Q1)
A = me.ReferenceFrame('A')
A.orient_axis(N, N.z, Q1)
A.set_ang_vel(N, U1*N.z)
# rolling_disc.al:16: SIMPROT(A, B, 1, Q2)
B = me.ReferenceFrame('B')
B.orient_axis(A, A.x, Q2)
B.set_ang_vel(A, U2*A.x)
# rolling_disc.al:17: SIMPROT(B, C, 2, Q3)
C = me.ReferenceFrame('C')
C.orient_axis(B, B.y, Q3)
C.set_ang_vel(B, U3*B.y)

# points: positions from the Newtonian origin, velocities in N of those with a mass or a load
CO = me.Point('CO')
NO = me.Point('NO')
CN = me.Point('CN')
# rolling_disc.al:24: P_NO_CO> = Q4*N1> + Q5*N2> + R*B3>
CO.set_pos(NO, Q4*N.x + Q5*N.y + R*B.z)
# rolling_disc.al:26: P_CO_CN> = -R*B3>
CN.set_pos(CO, (-R)*B.z)
# rolling_disc.al:25: V_CO_N> = DT(P_NO_CO>, N)
CO.set_vel(N, (R*U1*sm.sin(Q2)*sm.cos(Q1) + U4)*N.x + (R*U1*sm.sin(Q1)*sm.sin(Q2) + U5)*N.y + (-R*U2*sm.cos(Q2))*A.y + (-R*U2*sm.sin(Q2))*A.z)

# particles and rigid bodies: masses and central inertias
# rolling_disc.al:12: MASS C = M
# rolling_disc.al:13: INERTIA C, M*R^2/4, M*R^2/2, M*R^2/4
C_body = me.RigidBody('C', CO, C, M, (me.inertia(C, M*R**2/4, M*R**2/2, M*R**2/4), CO))
bodies = [C_body]

# loads: forces on points, torques on frames
# rolling_disc.al:34: GRAVITY(-G*N3>)
loads = [
    (CO, (-G*M)*N.z),
]

# kinematical differential equations (each = 0)
kd_eqs = [
    # rolling_disc.al:18: Q1' = U1
    Q1.diff(t) - U1,
    # rolling_disc.al:19: Q2' = U2
    Q2.diff(t) - U2,
    # rolling_disc.al:20: Q3' = U3
    Q3.diff(t) - U3,
    # rolling_disc.al:21: Q4' = U4
    Q4.diff(t) - U4,
    # rolling_disc.al:22: Q5' = U5
    Q5.diff(t) - U5,
]

# velocity constraints (each = 0), which give the dependent speeds (CONSTRAIN(DEPENDENT[...]));
# KanesMethod solves them by Cramer's rule: its default LU divides by pivots that
# vanish at some states where the constraints are regular (0/0)
# rolling_disc.al:30: DEPENDENT[1] = DOT(V_CN_N>, N1>)
# rolling_disc.al:31: DEPENDENT[2] = DOT(V_CN_N>, N2>)
# rolling_disc.al:32: CONSTRAIN(DEPENDENT[U4, U5])
velocity_constraints = [
    -R*U3*sm.cos(Q1) + U4,
    -R*U3*sm.sin(Q1) + U5,
]
dependent = [U4, U5]

kane = me.KanesMethod(N, q_ind=[Q1, Q2, Q3, Q4, Q5], u_ind=[U1, U2, U3], kd_eqs=kd_eqs, u_dependent=dependent, velocity_constraints=velocity_constraints, constraint_solver='CRAMER')
kane.kanes_equations(bodies, loads)

# as one system: full_mass * d(states)/dt = full_forcing
states = list(kane.q) + list(kane.u)
full_mass = kane.mass_matrix_full
full_forcing = kane.forcing_full

# the rates solved from the mass matrix, as the outputs use them
U1p = U1.diff(t)
U2p = U2.diff(t)
U3p = U3.diff(t)
intermediates = [
]
# those that need the solved rates
after_solving = [
]
unknowns = [U1p, U2p, U3p]
unknown_states = [5, 6, 7]

# values (SI units, radians) from the model's INPUT statements
constants = {G: 9.81, M: 2.0, R: 0.3}
initial_conditions = {Q1: 0.0, Q2: 0.08726646259971647, Q3: 0.0, Q4: 0.0, Q5: 0.0, U1: 0.0, U2: 0.0, U3: 8.0}
# each a number or a function of time; 0 unless given
specified = {}
integration = {'TINITIAL': 0.0, 'TFINAL': 3.0, 'INTEGSTP': 0.01, 'ABSERR': 1e-08, 'RELERR': 1e-07, 'PRINTINT': 1}
# scipy's method for the program's integrator: scipy has no kutta-merson (the program's)
integration_method = 'DOP853'
# OUTPUT columns: (label, unit, expression in the unit)
outputs = [
    ('T', 'sec', t),
    ('Q1', 'deg', Q1 * 180 / sm.pi),
    ('Q2', 'deg', Q2 * 180 / sm.pi),
    ('Q4', 'm', Q4),
    ('Q5', 'm', Q5),
]
# the dependent speeds start where the velocity constraints hold (once every
# constant has a value)
if None not in constants.values():
    at_start = {t: integration['TINITIAL'], **constants, **initial_conditions,
                **{s: v(integration['TINITIAL']) if callable(v) else v
                   for s, v in specified.items()}}
    coefficients, rest = sm.linear_eq_to_matrix(
        [me.msubs(c, kane.kindiffdict()) for c in velocity_constraints], dependent)
    initial_conditions.update(zip(dependent, np.linalg.solve(
        np.array(coefficients.xreplace(at_start), dtype=float),
        np.array(rest.xreplace(at_start), dtype=float).ravel())))


def expanded(expr):
    """`expr` with every intermediate replaced by what it is (large for large models)."""
    for name, value in reversed(intermediates + after_solving):
        expr = expr.xreplace({name: value})
    return expr


def numeric_functions():
    """full_mass, full_forcing and the outputs as numpy functions of (t, state, constants,
    specified values[, unknowns]), each computing the intermediates in order."""
    # every argument a Dummy: a model's constant named `sin` must not shadow numpy's
    plain = {f: sm.Dummy() for f in states + list(specified) + unknowns + list(constants)
             + [name for name, _ in intermediates + after_solving]}
    steps = [(plain[name], value.xreplace(plain)) for name, value in intermediates]
    late = [(plain[name], value.xreplace(plain)) for name, value in after_solving]
    arguments = [t, [plain[x] for x in states], [plain[c] for c in constants],
                 [plain[s] for s in specified]]

    def function(expr, more=(), after=()):
        def shared(e):
            # then sympy's common subexpressions: a KanesMethod's are not named as Z's
            common, reduced = sm.cse(e, list=False)
            return steps + list(after) + common, reduced
        return sm.lambdify(arguments + list(more), expr.xreplace(plain), "numpy", cse=shared)
    columns = sm.Matrix([e for _, _, e in outputs])
    return (function(full_mass), function(full_forcing),
            function(columns, [[plain[u] for u in unknowns]], late))


def integrate(tfinal=None):
    """The OUTPUT rows from TINITIAL to TFINAL (or `tfinal`) as Autolev's programs print
    them, as an array (a column per output)."""
    lacking = [str(c) for c, v in constants.items() if v is None]
    if lacking:
        raise ValueError(f"no value for {', '.join(lacking)}: give each in `constants`")
    mass, force, columns = numeric_functions()
    p = [constants[c] for c in constants]
    x0 = np.array([initial_conditions[x] for x in states], dtype=float)
    t0, t1 = integration["TINITIAL"], tfinal if tfinal is not None else integration["TFINAL"]

    def values_of_specified(time):
        return [v(time) if callable(v) else v for v in specified.values()]

    def rates_of(time, x):
        s = values_of_specified(time)
        return np.linalg.solve(np.asarray(mass(time, x, p, s), dtype=float),
                               np.asarray(force(time, x, p, s), dtype=float).ravel())

    def row_at(time, x):
        rate = rates_of(time, x)
        return np.asarray(columns(time, x, p, values_of_specified(time),
                                  [rate[k] for k in unknown_states]), dtype=float).ravel()

    # Autolev's loop: a step of INTEGSTP while T + INTEGSTP/100 falls short of TFINAL,
    # a row every PRINTINT steps and after the last (which may pass TFINAL)
    h, every = integration["INTEGSTP"], integration["PRINTINT"]

    def done(time):
        ahead = time + 0.01 * h
        return ahead >= t1 if t1 >= t0 else ahead <= t1
    times, time, steps = [t0], t0, 0
    while not done(time):
        time, steps = time + h, steps + 1
        if steps % every == 0 or done(time):
            times.append(time)
    if len(times) == 1:
        return np.array([row_at(t0, x0)])
    solution = solve_ivp(rates_of, (t0, times[-1]), x0, method=integration_method, t_eval=times,
                         rtol=integration["RELERR"], atol=integration["ABSERR"])
    if not solution.success:
        raise RuntimeError(solution.message)
    return np.array([row_at(time, x) for time, x in zip(solution.t, solution.y.T)])


def main(argv):
    try:
        rows = integrate()
    except ValueError as exc:
        sys.stderr.write(f"{__file__}: {exc}\n")
        return 1
    text = ",".join(label for label, _, _ in outputs) + "\n" + "".join(
        ",".join(repr(float(v)) for v in row) + "\n" for row in rows)
    if argv:
        with open(argv[0], "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
