"""block_pendulums: the model in sympy.physics.mechanics, written by autolev from
block_pendulums.al (CODE DYNAMICS block_pendulums.c).

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
U1 = me.dynamicsymbols('U1')
U2 = me.dynamicsymbols('U2')
U3 = me.dynamicsymbols('U3')

# specified quantities: functions of time (values in `specified`)
F = me.dynamicsymbols('F')
TQ = me.dynamicsymbols('TQ')

# constants
MA = sm.Symbol('MA')
MB = sm.Symbol('MB')
MC = sm.Symbol('MC')
IBZZ = sm.Symbol('IBZZ')
L = sm.Symbol('L')
G = sm.Symbol('G')
K = sm.Symbol('K')
CDAMP = sm.Symbol('CDAMP')
KT = sm.Symbol('KT')

# reference frames, oriented as the model orients them, with its angular velocities
N = me.ReferenceFrame('N')
# block_pendulums.al:19: SIMPROT(N, B, 3, Q2)
# block_pendulums.al:24: W_B_N> = U2*N3>
B = me.ReferenceFrame('B')
B.orient_axis(N, N.z, Q2)
B.set_ang_vel(N, U2*N.z)
# block_pendulums.al:20: SIMPROT(B, CF, 3, Q3)
# block_pendulums.al:25: W_CF_B> = U3*N3>
CF = me.ReferenceFrame('CF')
CF.orient_axis(B, B.z, Q3)
CF.set_ang_vel(B, U3*N.z)

# points: positions from the Newtonian origin, velocities in N of those with a mass or a load
A = me.Point('A')
C = me.Point('C')
BO = me.Point('BO')
NO = me.Point('NO')
PBC = me.Point('PBC')
# block_pendulums.al:27: P_NO_A> = Q1*N1>
A.set_pos(NO, Q1*N.x)
# block_pendulums.al:29: P_A_BO> = -2*L/3*B2>
BO.set_pos(A, (-2*L/3)*B.y)
# block_pendulums.al:30: P_BO_PBC> = -L/3*B2>
PBC.set_pos(BO, (-L/3)*B.y)
# block_pendulums.al:31: P_PBC_C> = -L*CF2>
C.set_pos(PBC, (-L)*CF.y)
# block_pendulums.al:28: V_A_N> = U1*N1>
A.set_vel(N, U1*N.x)
# block_pendulums.al:34: V2PTS(N, CF, PBC, C)
C.set_vel(N, (L*(-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*(U2 + U3) + L*U2*sm.cos(Q2) + U1)*N.x + (-L*(-sm.sin(Q2)*sm.cos(Q3) - sm.sin(Q3)*sm.cos(Q2))*(U2 + U3) + L*U2*sm.sin(Q2))*N.y)
# block_pendulums.al:32: V2PTS(N, B, A, BO)
BO.set_vel(N, (2*L*U2*sm.cos(Q2)/3 + U1)*N.x + 2*L*U2*sm.sin(Q2)/3*N.y)
NO.set_vel(N, me.Vector(0))

# particles and rigid bodies: masses and central inertias
# block_pendulums.al:16: MASS A = MA, B = MB, C = MC
A_particle = me.Particle('A', A, MA)
# block_pendulums.al:16: MASS A = MA, B = MB, C = MC
C_particle = me.Particle('C', C, MC)
# block_pendulums.al:16: MASS A = MA, B = MB, C = MC
# block_pendulums.al:17: INERTIA B, 0, 0, IBZZ
B_body = me.RigidBody('B', BO, B, MB, (me.inertia(B, 0, 0, IBZZ), BO))
bodies = [A_particle, C_particle, B_body]

# loads: forces on points, torques on frames
# block_pendulums.al:36: GRAVITY(-G*N2>)
loads = [
    (BO, (-G*MB)*N.y),
    # block_pendulums.al:37: FORCE(NO/A, (-K*Q1 - CDAMP*U1)*N1>)
    # block_pendulums.al:38: FORCE(A, F*N1>)
    (A, (-CDAMP*U1 - K*Q1 + F)*N.x + (-G*MA)*N.y),
    (C, (-G*MC)*N.y),
    # block_pendulums.al:37: FORCE(NO/A, (-K*Q1 - CDAMP*U1)*N1>)
    (NO, (CDAMP*U1 + K*Q1)*N.x),
    # block_pendulums.al:39: TORQUE(N/B, TQ*N3>)
    # block_pendulums.al:40: TORQUE(B/CF, -KT*Q3*N3>)
    (B, (KT*Q3 + TQ)*N.z),
    # block_pendulums.al:39: TORQUE(N/B, TQ*N3>)
    (N, (-TQ)*N.z),
    # block_pendulums.al:40: TORQUE(B/CF, -KT*Q3*N3>)
    (CF, (-KT*Q3)*N.z),
]

# kinematical differential equations (each = 0)
kd_eqs = [
    # block_pendulums.al:21: Q1' = U1
    Q1.diff(t) - U1,
    # block_pendulums.al:22: Q2' = U2
    Q2.diff(t) - U2,
    # block_pendulums.al:23: Q3' = U3
    Q3.diff(t) - U3,
]

kane = me.KanesMethod(N, q_ind=[Q1, Q2, Q3], u_ind=[U1, U2, U3], kd_eqs=kd_eqs)
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
unknown_states = [3, 4, 5]

# values (SI units, radians) from the model's INPUT statements
constants = {CDAMP: 0.5, G: 9.81, IBZZ: 0.1, K: 20.0, KT: 2.0, L: 1.0, MA: 2.0, MB: 1.0, MC: 0.5}
initial_conditions = {Q1: 0.1, Q2: 0.3490658503988659, Q3: -0.17453292519943295, U1: 0.0, U2: 0.0, U3: 0.0}
# each a number or a function of time; 0 unless given
specified = {F: 0.0, TQ: 0.0}
integration = {'TINITIAL': 0.0, 'TFINAL': 5.0, 'INTEGSTP': 0.01, 'ABSERR': 1e-08, 'RELERR': 1e-07, 'PRINTINT': 1}
# scipy's method for the program's integrator: scipy has no kutta-merson (the program's)
integration_method = 'DOP853'
# OUTPUT columns: (label, unit, expression in the unit)
outputs = [
    ('T', '', t),
    ('Q1', '', Q1),
    ('Q2', 'deg', Q2 * 180 / sm.pi),
    ('Q3', 'deg', Q3 * 180 / sm.pi),
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
