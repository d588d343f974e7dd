"""rolling_disc: its equations of motion as SymPy expressions, written by autolev from
rolling_disc.al (CODE DYNAMICS rolling_disc.c).

Level: equations.  The state, the rates given explicitly, and the mass matrix and
forcing from which the other rates (`unknowns`) are solved, as Autolev's Kane's
method formed them, with every intermediate (Autolev's Z's) a named assignment.
Not the mechanics level: sympy's KanesMethod here takes no dependent or auxiliary speeds
(U4, U5).
Importing defines `system` (a sympy.physics.mechanics.SymbolicSystem: full_mass *
d(states)/dt = full_forcing, in the intermediates), `constants`,
`initial_conditions` and `specified`;
`python THIS.py [OUT.csv]` integrates from TINITIAL to TFINAL with scipy (DOP853,
RELERR and ABSERR) and writes the OUTPUT columns as CSV.
"""
import sys

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me
from scipy.integrate import solve_ivp

t = me.dynamicsymbols._t

# the state: functions of time
Q1 = me.dynamicsymbols('Q1')
Q2 = me.dynamicsymbols('Q2')
Q3 = me.dynamicsymbols('Q3')
Q4 = me.dynamicsymbols('Q4')
Q5 = me.dynamicsymbols('Q5')
U1 = me.dynamicsymbols('U1')
U2 = me.dynamicsymbols('U2')
U3 = me.dynamicsymbols('U3')

# constants
G = sm.Symbol('G')
M = sm.Symbol('M')
R = sm.Symbol('R')

# the rates solved from the mass matrix
U1p = U1.diff(t)
U2p = U2.diff(t)
U3p = U3.diff(t)

# intermediates (Autolev's Z's) and the model's definitions, as functions of
# time, and what each is, in the order they are computed; `expanded(expr)`
# replaces them in an expression
Q1p = me.dynamicsymbols('Q1p')
Q3p = me.dynamicsymbols('Q3p')
z3 = me.dynamicsymbols('z3')
z5 = me.dynamicsymbols('z5')
U4 = me.dynamicsymbols('U4')
z4 = me.dynamicsymbols('z4')
z6 = me.dynamicsymbols('z6')
U5 = me.dynamicsymbols('U5')
z39 = me.dynamicsymbols('z39')
z41 = me.dynamicsymbols('z41')
z42 = me.dynamicsymbols('z42')
z44 = me.dynamicsymbols('z44')
z40 = me.dynamicsymbols('z40')
z43 = me.dynamicsymbols('z43')
z45 = me.dynamicsymbols('z45')
z46 = me.dynamicsymbols('z46')
z47 = me.dynamicsymbols('z47')
z48 = me.dynamicsymbols('z48')
z49 = me.dynamicsymbols('z49')
z50 = me.dynamicsymbols('z50')
Q2p = me.dynamicsymbols('Q2p')
z13 = me.dynamicsymbols('z13')
z14 = me.dynamicsymbols('z14')
z27 = me.dynamicsymbols('z27')
z29 = me.dynamicsymbols('z29')
z31 = me.dynamicsymbols('z31')
z28 = me.dynamicsymbols('z28')
z33 = me.dynamicsymbols('z33')
z51 = me.dynamicsymbols('z51')
z52 = me.dynamicsymbols('z52')
z53 = me.dynamicsymbols('z53')
z54 = me.dynamicsymbols('z54')
z55 = me.dynamicsymbols('z55')
z56 = me.dynamicsymbols('z56')
z18 = me.dynamicsymbols('z18')
z17 = me.dynamicsymbols('z17')
z19 = me.dynamicsymbols('z19')
z20 = me.dynamicsymbols('z20')
z21 = me.dynamicsymbols('z21')
z57 = me.dynamicsymbols('z57')
z58 = me.dynamicsymbols('z58')
z22 = me.dynamicsymbols('z22')
z23 = me.dynamicsymbols('z23')
z59 = me.dynamicsymbols('z59')
z60 = me.dynamicsymbols('z60')
z30 = me.dynamicsymbols('z30')
z34 = me.dynamicsymbols('z34')
z35 = me.dynamicsymbols('z35')
z61 = me.dynamicsymbols('z61')
z62 = me.dynamicsymbols('z62')
z32 = me.dynamicsymbols('z32')
z63 = me.dynamicsymbols('z63')
intermediates = [
    (Q1p, U1),
    (Q3p, U3),
    (z3, -Q1p*R*sm.sin(Q2)*sm.cos(Q1)),
    (z5, -Q1p*R*sm.sin(Q2)*sm.cos(Q1) + Q3p*R*sm.cos(Q1) - z3),
    (U4, z5),
    (z4, -Q1p*R*sm.sin(Q1)*sm.sin(Q2)),
    (z6, -Q1p*R*sm.sin(Q1)*sm.sin(Q2) + Q3p*R*sm.sin(Q1) - z4),
    (U5, z6),
    (z39, -M*R**2*sm.sin(Q3)*sm.cos(Q2)/4),
    (z41, M*R**2*sm.sin(Q2)/2),
    (z42, M*R**2*sm.cos(Q2)*sm.cos(Q3)/4),
    (z44, -M*R**2*sm.sin(Q1)**2*sm.sin(Q2)**2 - M*R**2*sm.sin(Q2)**2*sm.cos(Q1)**2 + z39*sm.sin(Q3)*sm.cos(Q2) - z41*sm.sin(Q2) - z42*sm.cos(Q2)*sm.cos(Q3)),
    (z40, M*R**2*sm.cos(Q3)/4),
    (z43, M*R**2*sm.sin(Q3)/4),
    (z45, z40*sm.sin(Q3)*sm.cos(Q2) - z43*sm.cos(Q2)*sm.cos(Q3)),
    (z46, -M*R**2*sm.sin(Q1)**2*sm.sin(Q2) - M*R**2*sm.sin(Q2)*sm.cos(Q1)**2 - M*R**2*sm.sin(Q2)/2),
    (z47, -z39*sm.cos(Q3) - z42*sm.sin(Q3)),
    (z48, -M*R**2*sm.sin(Q2)**2 - M*R**2*sm.cos(Q2)**2 - z40*sm.cos(Q3) - z43*sm.sin(Q3)),
    (z49, -M*R**2*sm.sin(Q1)**2*sm.sin(Q2) - M*R**2*sm.sin(Q2)*sm.cos(Q1)**2 - z41),
    (z50, -M*R**2*sm.sin(Q1)**2 - M*R**2*sm.cos(Q1)**2 - M*R**2/2),
    (Q2p, U2),
    (z13, Q1p*Q2p*R*sm.cos(Q1)*sm.cos(Q2)),
    (z14, Q1p*Q2p*R*sm.sin(Q1)*sm.cos(Q2)),
    (z27, M*R**2*(-Q1p*sm.sin(Q3)*sm.cos(Q2) + Q2p*sm.cos(Q3))/4),
    (z29, M*R**2*(Q1p*sm.cos(Q2)*sm.cos(Q3) + Q2p*sm.sin(Q3))/4),
    (z31, -Q3p*(z27*sm.cos(Q3) + z29*sm.sin(Q3))),
    (z28, M*R**2*(Q1p*sm.sin(Q2) + Q3p)/2),
    (z33, Q2p*(z27*sm.sin(Q2)*sm.sin(Q3) + z28*sm.cos(Q2) - z29*sm.sin(Q2)*sm.cos(Q3))),
    (z51, Q1p**2*R*sm.sin(Q1)*sm.sin(Q2) - Q1p*Q2p*R*sm.cos(Q1)*sm.cos(Q2)),
    (z52, -Q1p*Q2p*R*sm.cos(Q1)*sm.cos(Q2) + Q1p*(Q1p*R*sm.sin(Q1)*sm.sin(Q2) - Q3p*R*sm.sin(Q1)) - z51),
    (z53, -Q1p**2*R*sm.sin(Q1)*sm.sin(Q2) + Q1p*Q2p*R*sm.cos(Q1)*sm.cos(Q2) + z52),
    (z54, -Q1p**2*R*sm.sin(Q2)*sm.cos(Q1) - Q1p*Q2p*R*sm.sin(Q1)*sm.cos(Q2)),
    (z55, -Q1p*Q2p*R*sm.sin(Q1)*sm.cos(Q2) + Q1p*(-Q1p*R*sm.sin(Q2)*sm.cos(Q1) + Q3p*R*sm.cos(Q1)) - z54),
    (z56, Q1p**2*R*sm.sin(Q2)*sm.cos(Q1) + Q1p*Q2p*R*sm.sin(Q1)*sm.cos(Q2) + z55),
    (z18, -Q1p*Q3p*sm.sin(Q1)*sm.cos(Q2)),
    (z17, -Q1p*Q3p*sm.cos(Q1)*sm.cos(Q2)),
    (z19, -Q1p*Q2p*sm.sin(Q1) + z17),
    (z20, -sm.sin(Q1)*sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q1)*sm.cos(Q3)),
    (z21, sm.sin(Q1)*sm.cos(Q3) + sm.sin(Q2)*sm.sin(Q3)*sm.cos(Q1)),
    (z57, M*R**2*(-Q2p*Q3p*sm.sin(Q2)**2*sm.sin(Q3) - Q2p*Q3p*sm.sin(Q3)*sm.cos(Q2)**2 + z19*z20 + z21*(Q1p*Q2p*sm.cos(Q1) + z18))/4),
    (z58, M*R**2*(-z19*sm.sin(Q1)*sm.cos(Q2) + (Q1p*Q2p*sm.cos(Q1) + z18)*sm.cos(Q1)*sm.cos(Q2))/2),
    (z22, sm.sin(Q1)*sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q1)),
    (z23, sm.sin(Q1)*sm.sin(Q3) - sm.sin(Q2)*sm.cos(Q1)*sm.cos(Q3)),
    (z59, M*R**2*(Q2p*Q3p*sm.sin(Q2)**2*sm.cos(Q3) + Q2p*Q3p*sm.cos(Q2)**2*sm.cos(Q3) + z19*z22 + z23*(Q1p*Q2p*sm.cos(Q1) + z18))/4),
    (z60, -M*R*(z13 + z53)*sm.sin(Q2)*sm.cos(Q1) - M*R*(z14 + z56)*sm.sin(Q1)*sm.sin(Q2) - z31*sm.cos(Q2) - z33 + z57*sm.sin(Q3)*sm.cos(Q2) - z58*sm.sin(Q2) - z59*sm.cos(Q2)*sm.cos(Q3)),
    (z30, Q3p*(-z27*sm.sin(Q3) + z29*sm.cos(Q3))),
    (z34, -Q1p*(z21*z27 + z23*z29 + z28*sm.cos(Q1)*sm.cos(Q2))),
    (z35, Q1p*(z20*z27 + z22*z29 - z28*sm.sin(Q1)*sm.cos(Q2))),
    (z61, -Q2p**2*R*sm.cos(Q2)),
    (z62, M*Q2p**2*R**2*sm.sin(Q2)*sm.cos(Q2) + M*R*z61*sm.sin(Q2) - R*(M*(z13 + z53)*sm.sin(Q1) - M*(z14 + z56)*sm.cos(Q1))*sm.cos(Q2) - z30 - z34*sm.cos(Q1) - z35*sm.sin(Q1) - z57*sm.cos(Q3) - z59*sm.sin(Q3)),
    (z32, -Q2p*(-z27*sm.sin(Q3)*sm.cos(Q2) + z28*sm.sin(Q2) + z29*sm.cos(Q2)*sm.cos(Q3))),
    (z63, -M*R*(z13 + z53)*sm.cos(Q1) - M*R*(z14 + z56)*sm.sin(Q1) - z32*sm.cos(Q2) - z33*sm.sin(Q2) + z34*sm.sin(Q1)*sm.cos(Q2) - z35*sm.cos(Q1)*sm.cos(Q2) - z58),
]
# those that need the solved rates (outputs only)
after_solving = [
]

states = [Q1, Q2, Q3, Q4, Q5, U1, U2, U3]
# d(state)/dt where it is given; None where it is solved (`unknowns`)
rates = [U1, U2, U3, U4, U5, None, None, None]
unknowns = [U1p, U2p, U3p]
unknown_states = [5, 6, 7]
mass_matrix = sm.Matrix(3, 3, [-z44, -z45, -z46, -z47, -z48, 0, -z49, 0, -z50])
forcing = sm.Matrix(3, 1, [z60, G*M*R*sm.sin(Q2) + z62, z63])

# as one system: full_mass * d(states)/dt = full_forcing
full_mass = sm.eye(len(states))
full_forcing = sm.Matrix([0 if r is None else r for r in rates])
for row, k in enumerate(unknown_states):
    full_mass[k, k] = 0
    for column, j in enumerate(unknown_states):
        full_mass[k, j] = mass_matrix[row, column]
    full_forcing[k] = forcing[row]
system = me.SymbolicSystem(states, full_forcing, mass_matrix=full_mass)

# values (SI units, radians) from the model's INPUT statements
constants = {G: 9.81, M: 2.0, R: 0.3}
initial_conditions = {Q1: 0.0, Q2: 0.08726646259971647, Q3: 0.0, Q4: 0.0, Q5: 0.0, U1: 0.0, U2: 0.0, U3: 8.0}
# each a number or a function of time; 0 unless given
specified = {}
integration = {'TINITIAL': 0.0, 'TFINAL': 3.0, 'INTEGSTP': 0.01, 'ABSERR': 1e-08, 'RELERR': 1e-07, 'PRINTINT': 1}
# OUTPUT columns: (label, unit, expression in the unit)
outputs = [
    ('T', 'sec', t),
    ('Q1', 'deg', Q1 * 180 / sm.pi),
    ('Q2', 'deg', Q2 * 180 / sm.pi),
    ('Q4', 'm', Q4),
    ('Q5', 'm', Q5),
]


def expanded(expr):
    """`expr` with every intermediate replaced by what it is (large for large models)."""
    for name, value in reversed(intermediates + after_solving):
        expr = expr.xreplace({name: value})
    return expr


def numeric_functions():
    """full_mass, full_forcing and the outputs as numpy functions of (t, state, constants,
    specified values[, unknowns]), each computing the intermediates in order."""
    plain = {f: sm.Dummy() for f in states + list(specified) + unknowns
             + [name for name, _ in intermediates + after_solving]}
    steps = [(plain[name], value.xreplace(plain)) for name, value in intermediates]
    late = [(plain[name], value.xreplace(plain)) for name, value in after_solving]
    arguments = [t, [plain[x] for x in states], list(constants),
                 [plain[s] for s in specified]]

    def function(expr, more=(), after=()):
        return sm.lambdify(arguments + list(more), expr.xreplace(plain), "numpy",
                           cse=lambda e: (steps + list(after), e))
    columns = sm.Matrix([e for _, _, e in outputs])
    return (function(full_mass), function(full_forcing),
            function(columns, [[plain[u] for u in unknowns]], late))


def integrate(tfinal=None):
    """The OUTPUT rows from TINITIAL to TFINAL (or `tfinal`) as Autolev's programs print
    them, as an array (a column per output)."""
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
    solution = solve_ivp(rates_of, (t0, times[-1]), x0, method="DOP853", t_eval=times,
                         rtol=integration["RELERR"], atol=integration["ABSERR"])
    if not solution.success:
        raise RuntimeError(solution.message)
    return np.array([row_at(time, x) for time, x in zip(solution.t, solution.y.T)])


def main(argv):
    rows = integrate()
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
