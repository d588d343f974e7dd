"""double_pendulum: the model in sympy.physics.mechanics, written by autolev from
double_pendulum.al (CODE DYNAMICS double_pendulum.c).

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
U1 = me.dynamicsymbols('U1')
U2 = me.dynamicsymbols('U2')

# constants
L1 = sm.Symbol('L1')
L2 = sm.Symbol('L2')
M1 = sm.Symbol('M1')
M2 = sm.Symbol('M2')
G = sm.Symbol('G')

# reference frames, oriented as the model orients them, with its angular velocities
N = me.ReferenceFrame('N')
# double_pendulum.al:16: SIMPROT(N, A, 3, Q1)
# double_pendulum.al:22: W_A_N> = U1*N3>
A = me.ReferenceFrame('A')
A.orient_axis(N, N.z, Q1)
A.set_ang_vel(N, U1*N.z)
# double_pendulum.al:17: SIMPROT(N, B, 3, Q2)
# double_pendulum.al:23: W_B_N> = U2*N3>
B = me.ReferenceFrame('B')
B.orient_axis(N, N.z, Q2)
B.set_ang_vel(N, U2*N.z)

# points: positions from the Newtonian origin, velocities in N of those with a mass or a load
P1 = me.Point('P1')
P2 = me.Point('P2')
NO = me.Point('NO')
# double_pendulum.al:26: P_NO_P1> = L1*A1>
P1.set_pos(NO, L1*A.x)
# double_pendulum.al:27: P_P1_P2> = L2*B1>
P2.set_pos(P1, L2*B.x)
# double_pendulum.al:29: V2PTS(N, A, NO, P1)
P1.set_vel(N, (-L1*U1*sm.sin(Q1))*N.x + L1*U1*sm.cos(Q1)*N.y)
# double_pendulum.al:30: V2PTS(N, B, P1, P2)
P2.set_vel(N, (-L1*U1*sm.sin(Q1) - L2*U2*sm.sin(Q2))*N.x + (L1*U1*sm.cos(Q1) + L2*U2*sm.cos(Q2))*N.y)

# particles and rigid bodies: masses and central inertias
# double_pendulum.al:13: MASS P1 = M1, P2 = M2
P1_particle = me.Particle('P1', P1, M1)
# double_pendulum.al:13: MASS P1 = M1, P2 = M2
P2_particle = me.Particle('P2', P2, M2)
bodies = [P1_particle, P2_particle]

# loads: forces on points, torques on frames
# double_pendulum.al:33: GRAVITY(G*N1>)
loads = [
    (P1, G*M1*N.x),
    (P2, G*M2*N.x),
]

# kinematical differential equations (each = 0)
kd_eqs = [
    # double_pendulum.al:20: Q1' = U1
    Q1.diff(t) - U1,
    # double_pendulum.al:21: Q2' = U2
    Q2.diff(t) - U2,
]

kane = me.KanesMethod(N, q_ind=[Q1, Q2], u_ind=[U1, U2], kd_eqs=kd_eqs)
kane.kanes_equations(bodies, loads)

# as one system: full_mass * d(states)/dt = full_forcing
states = list(kane.q) + list(kane.u)
full_mass = kane.mass_matrix_full
full_forcing = kane.forcing_full

# the rates solved from the mass matrix, as the outputs use them
U1p = U1.diff(t)
U2p = U2.diff(t)
# intermediates the outputs use (Autolev's Z's, the model's definitions), as
# functions of time, and what each is, in the order they are computed
z8 = me.dynamicsymbols('z8')
intermediates = [
    (z8, M1*(L1**2*U1**2*sm.sin(Q1)**2 + L1**2*U1**2*sm.cos(Q1)**2)/2 + M2*((-L1*U1*sm.sin(Q1) - L2*U2*sm.sin(Q2))**2 + (L1*U1*sm.cos(Q1) + L2*U2*sm.cos(Q2))**2)/2),
]
# those that need the solved rates
after_solving = [
]
unknowns = [U1p, U2p]
unknown_states = [2, 3]

# values (SI units, radians) from the model's INPUT statements
constants = {G: 9.81, L1: 1.0, L2: 1.0, M1: 1.0, M2: 1.0}
initial_conditions = {Q1: 0.5235987755982988, Q2: 1.0471975511965976, U1: 0.0, U2: 0.0}
# each a number or a function of time; 0 unless given
specified = {}
integration = {'TINITIAL': 0.0, 'TFINAL': 10.0, 'INTEGSTP': 0.01, 'ABSERR': 1e-08, 'RELERR': 1e-08, 'PRINTINT': 1}
# scipy's method for the program's integrator: scipy has no kutta-merson (the program's)
integration_method = 'DOP853'
# OUTPUT columns: (label, unit, expression in the unit)
outputs = [
    ('T', 'sec', t),
    ('Q1', 'deg', Q1 * 180 / sm.pi),
    ('Q2', 'deg', Q2 * 180 / sm.pi),
    ('U1', 'rad/sec', U1),
    ('U2', 'rad/sec', U2),
    ('T', 'sec', t),
    ('ENERGY', 'joules', -G*L1*M1*sm.cos(Q1) - G*M2*(L1*sm.cos(Q1) + L2*sm.cos(Q2)) + z8),
]


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
