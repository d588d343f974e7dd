"""nlink_pendulum: the model in sympy.physics.mechanics, written by autolev from
nlink_pendulum.al (CODE DYNAMICS nlink_pendulum.c).

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
U1 = me.dynamicsymbols('U1')
U2 = me.dynamicsymbols('U2')
U3 = me.dynamicsymbols('U3')
U4 = me.dynamicsymbols('U4')

# constants
L = sm.Symbol('L')
M = sm.Symbol('M')
G = sm.Symbol('G')

# reference frames, oriented as the model orients them, with its angular velocities
N = me.ReferenceFrame('N')
# nlink_pendulum.al:17: SIMPROT(N, A, 3, Q1)
# nlink_pendulum.al:26: W_A_N> = U1*N3>
A = me.ReferenceFrame('A')
A.orient_axis(N, N.z, Q1)
A.set_ang_vel(N, U1*N.z)
# nlink_pendulum.al:18: SIMPROT(A, B, 3, Q2)
# nlink_pendulum.al:27: W_B_A> = U2*N3>
B = me.ReferenceFrame('B')
B.orient_axis(A, A.z, Q2)
B.set_ang_vel(A, U2*N.z)
# nlink_pendulum.al:19: SIMPROT(B, C, 3, Q3)
# nlink_pendulum.al:28: W_C_B> = U3*N3>
C = me.ReferenceFrame('C')
C.orient_axis(B, B.z, Q3)
C.set_ang_vel(B, U3*N.z)
# nlink_pendulum.al:20: SIMPROT(C, D, 3, Q4)
# nlink_pendulum.al:29: W_D_C> = U4*N3>
D = me.ReferenceFrame('D')
D.orient_axis(C, C.z, Q4)
D.set_ang_vel(C, U4*N.z)

# points: positions from the Newtonian origin, velocities in N of those with a mass or a load
AO = me.Point('AO')
BO = me.Point('BO')
CO = me.Point('CO')
DO = me.Point('DO')
NO = me.Point('NO')
P1 = me.Point('P1')
P2 = me.Point('P2')
P3 = me.Point('P3')
# nlink_pendulum.al:31: P_NO_AO> = L/2*A1>
AO.set_pos(NO, L/2*A.x)
# nlink_pendulum.al:32: P_NO_P1> = L*A1>
P1.set_pos(NO, L*A.x)
# nlink_pendulum.al:33: P_P1_BO> = L/2*B1>
BO.set_pos(P1, L/2*B.x)
# nlink_pendulum.al:34: P_P1_P2> = L*B1>
P2.set_pos(P1, L*B.x)
# nlink_pendulum.al:35: P_P2_CO> = L/2*C1>
CO.set_pos(P2, L/2*C.x)
# nlink_pendulum.al:36: P_P2_P3> = L*C1>
P3.set_pos(P2, L*C.x)
# nlink_pendulum.al:37: P_P3_DO> = L/2*D1>
DO.set_pos(P3, L/2*D.x)
# nlink_pendulum.al:39: V2PTS(N, A, NO, AO)
AO.set_vel(N, (-L*U1*sm.sin(Q1)/2)*N.x + L*U1*sm.cos(Q1)/2*N.y)
# nlink_pendulum.al:41: V2PTS(N, B, P1, BO)
BO.set_vel(N, (-L*(sm.sin(Q1)*sm.cos(Q2) + sm.sin(Q2)*sm.cos(Q1))*(U1 + U2)/2 - L*U1*sm.sin(Q1))*N.x + (L*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2))*(U1 + U2)/2 + L*U1*sm.cos(Q1))*N.y)
# nlink_pendulum.al:43: V2PTS(N, C, P2, CO)
CO.set_vel(N, (-L*((-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*sm.sin(Q1) + (sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2))*sm.cos(Q1))*(U1 + U2 + U3)/2 - L*(sm.sin(Q1)*sm.cos(Q2) + sm.sin(Q2)*sm.cos(Q1))*(U1 + U2) - L*U1*sm.sin(Q1))*N.x + (L*((-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*sm.cos(Q1) - (sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2))*sm.sin(Q1))*(U1 + U2 + U3)/2 + L*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2))*(U1 + U2) + L*U1*sm.cos(Q1))*N.y)
# nlink_pendulum.al:45: V2PTS(N, D, P3, DO)
DO.set_vel(N, (-L*(((-sm.sin(Q3)*sm.sin(Q4) + sm.cos(Q3)*sm.cos(Q4))*sm.sin(Q2) + (sm.sin(Q3)*sm.cos(Q4) + sm.sin(Q4)*sm.cos(Q3))*sm.cos(Q2))*sm.cos(Q1) + ((-sm.sin(Q3)*sm.sin(Q4) + sm.cos(Q3)*sm.cos(Q4))*sm.cos(Q2) - (sm.sin(Q3)*sm.cos(Q4) + sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q2))*sm.sin(Q1))*(U1 + U2 + U3 + U4)/2 - L*((-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*sm.sin(Q1) + (sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2))*sm.cos(Q1))*(U1 + U2 + U3) - L*(sm.sin(Q1)*sm.cos(Q2) + sm.sin(Q2)*sm.cos(Q1))*(U1 + U2) - L*U1*sm.sin(Q1))*N.x + (L*(-((-sm.sin(Q3)*sm.sin(Q4) + sm.cos(Q3)*sm.cos(Q4))*sm.sin(Q2) + (sm.sin(Q3)*sm.cos(Q4) + sm.sin(Q4)*sm.cos(Q3))*sm.cos(Q2))*sm.sin(Q1) + ((-sm.sin(Q3)*sm.sin(Q4) + sm.cos(Q3)*sm.cos(Q4))*sm.cos(Q2) - (sm.sin(Q3)*sm.cos(Q4) + sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q2))*sm.cos(Q1))*(U1 + U2 + U3 + U4)/2 + L*((-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*sm.cos(Q1) - (sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2))*sm.sin(Q1))*(U1 + U2 + U3) + L*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2))*(U1 + U2) + L*U1*sm.cos(Q1))*N.y)

# particles and rigid bodies: masses and central inertias
# nlink_pendulum.al:11: MASS A = M, B = M, C = M, D = M
# nlink_pendulum.al:12: INERTIA A, 0, 0, M*L^2/12
A_body = me.RigidBody('A', AO, A, M, (me.inertia(A, 0, 0, L**2*M/12), AO))
# nlink_pendulum.al:11: MASS A = M, B = M, C = M, D = M
# nlink_pendulum.al:13: INERTIA B, 0, 0, M*L^2/12
B_body = me.RigidBody('B', BO, B, M, (me.inertia(B, 0, 0, L**2*M/12), BO))
# nlink_pendulum.al:11: MASS A = M, B = M, C = M, D = M
# nlink_pendulum.al:14: INERTIA C, 0, 0, M*L^2/12
C_body = me.RigidBody('C', CO, C, M, (me.inertia(C, 0, 0, L**2*M/12), CO))
# nlink_pendulum.al:11: MASS A = M, B = M, C = M, D = M
# nlink_pendulum.al:15: INERTIA D, 0, 0, M*L^2/12
D_body = me.RigidBody('D', DO, D, M, (me.inertia(D, 0, 0, L**2*M/12), DO))
bodies = [A_body, B_body, C_body, D_body]

# loads: forces on points, torques on frames
# nlink_pendulum.al:47: GRAVITY(G*N1>)
loads = [
    (AO, G*M*N.x),
    (BO, G*M*N.x),
    (CO, G*M*N.x),
    (DO, G*M*N.x),
]

# kinematical differential equations (each = 0)
kd_eqs = [
    # nlink_pendulum.al:22: Q1' = U1
    Q1.diff(t) - U1,
    # nlink_pendulum.al:23: Q2' = U2
    Q2.diff(t) - U2,
    # nlink_pendulum.al:24: Q3' = U3
    Q3.diff(t) - U3,
    # nlink_pendulum.al:25: Q4' = U4
    Q4.diff(t) - U4,
]

kane = me.KanesMethod(N, q_ind=[Q1, Q2, Q3, Q4], u_ind=[U1, U2, U3, U4], kd_eqs=kd_eqs)
kane.kanes_equations(bodies, loads)

# as one system: full_mass * d(states)/dt = full_forcing
states = list(kane.q) + list(kane.u)
full_mass = kane.mass_matrix_full
full_forcing = kane.forcing_full

# the rates solved from the mass matrix, as the outputs use them
U1p = U1.diff(t)
U2p = U2.diff(t)
U3p = U3.diff(t)
U4p = U4.diff(t)
intermediates = [
]
# those that need the solved rates
after_solving = [
]
unknowns = [U1p, U2p, U3p, U4p]
unknown_states = [4, 5, 6, 7]

# values (SI units, radians) from the model's INPUT statements
constants = {G: 9.81, L: 0.5, M: 1.0}
initial_conditions = {Q1: 0.3490658503988659, Q2: 0.17453292519943295, Q3: -0.17453292519943295, Q4: 0.08726646259971647, U1: 0.0, U2: 0.0, U3: 0.0, U4: 0.0}
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
    ('Q3', 'deg', Q3 * 180 / sm.pi),
    ('Q4', 'deg', Q4 * 180 / sm.pi),
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
