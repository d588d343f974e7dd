"""fourbar: its equations of motion as SymPy expressions, written by autolev from
fourbar.al (CODE DYNAMICS fourbar.c).

Level: equations.  The state, the rates given explicitly, and the mass matrix and
forcing from which the other rates (`unknowns`) are solved, as Autolev's Kane's
method formed them, with every intermediate (Autolev's Z's) a named assignment.
Not the mechanics level: sympy's KanesMethod here takes no dependent or auxiliary speeds
(U2, U3, UA1, UA2).
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
U1 = me.dynamicsymbols('U1')

# constants
G = sm.Symbol('G')
L2 = sm.Symbol('L2')
L3 = sm.Symbol('L3')
L4 = sm.Symbol('L4')
RHO = sm.Symbol('RHO')

# the rates solved from the mass matrix
U1p = U1.diff(t)

# intermediates (Autolev's Z's) and the model's definitions, as functions of
# time, and what each is, in the order they are computed; `expanded(expr)`
# replaces them in an expression
UA1 = me.dynamicsymbols('UA1')
UA1p = me.dynamicsymbols('UA1p')
UA2 = me.dynamicsymbols('UA2')
UA2p = me.dynamicsymbols('UA2p')
z4 = me.dynamicsymbols('z4')
z6 = me.dynamicsymbols('z6')
z7 = me.dynamicsymbols('z7')
z1 = me.dynamicsymbols('z1')
z3 = me.dynamicsymbols('z3')
z9 = me.dynamicsymbols('z9')
z14 = me.dynamicsymbols('z14')
z31 = me.dynamicsymbols('z31')
z32 = me.dynamicsymbols('z32')
z40 = me.dynamicsymbols('z40')
z41 = me.dynamicsymbols('z41')
z42 = me.dynamicsymbols('z42')
z43 = me.dynamicsymbols('z43')
z44 = me.dynamicsymbols('z44')
Q1p = me.dynamicsymbols('Q1p')
z15 = me.dynamicsymbols('z15')
U2 = me.dynamicsymbols('U2')
Q2p = me.dynamicsymbols('Q2p')
z17 = me.dynamicsymbols('z17')
z18 = me.dynamicsymbols('z18')
z16 = me.dynamicsymbols('z16')
U3 = me.dynamicsymbols('U3')
Q3p = me.dynamicsymbols('Q3p')
z19 = me.dynamicsymbols('z19')
z20 = me.dynamicsymbols('z20')
z21 = me.dynamicsymbols('z21')
z22 = me.dynamicsymbols('z22')
z23 = me.dynamicsymbols('z23')
z24 = me.dynamicsymbols('z24')
z25 = me.dynamicsymbols('z25')
U2p = me.dynamicsymbols('U2p')
z55 = me.dynamicsymbols('z55')
z56 = me.dynamicsymbols('z56')
z57 = me.dynamicsymbols('z57')
z26 = me.dynamicsymbols('z26')
z27 = me.dynamicsymbols('z27')
U3p = me.dynamicsymbols('U3p')
z59 = me.dynamicsymbols('z59')
z61 = me.dynamicsymbols('z61')
z60 = me.dynamicsymbols('z60')
z62 = me.dynamicsymbols('z62')
z63 = me.dynamicsymbols('z63')
z66 = me.dynamicsymbols('z66')
z69 = me.dynamicsymbols('z69')
z71 = me.dynamicsymbols('z71')
F1 = me.dynamicsymbols('F1')
z33 = me.dynamicsymbols('z33')
z34 = me.dynamicsymbols('z34')
z45 = me.dynamicsymbols('z45')
z46 = me.dynamicsymbols('z46')
z47 = me.dynamicsymbols('z47')
z48 = me.dynamicsymbols('z48')
z49 = me.dynamicsymbols('z49')
z67 = me.dynamicsymbols('z67')
z70 = me.dynamicsymbols('z70')
z72 = me.dynamicsymbols('z72')
F2 = me.dynamicsymbols('F2')
z28 = me.dynamicsymbols('z28')
z30 = me.dynamicsymbols('z30')
z35 = me.dynamicsymbols('z35')
z38 = me.dynamicsymbols('z38')
z39 = me.dynamicsymbols('z39')
z50 = me.dynamicsymbols('z50')
z29 = me.dynamicsymbols('z29')
z36 = me.dynamicsymbols('z36')
z37 = me.dynamicsymbols('z37')
z65 = me.dynamicsymbols('z65')
z73 = me.dynamicsymbols('z73')
z74 = me.dynamicsymbols('z74')
z75 = me.dynamicsymbols('z75')
z76 = me.dynamicsymbols('z76')
z77 = me.dynamicsymbols('z77')
z78 = me.dynamicsymbols('z78')
z79 = me.dynamicsymbols('z79')
z80 = me.dynamicsymbols('z80')
z81 = me.dynamicsymbols('z81')
z82 = me.dynamicsymbols('z82')
z83 = me.dynamicsymbols('z83')
z84 = me.dynamicsymbols('z84')
z85 = me.dynamicsymbols('z85')
z86 = me.dynamicsymbols('z86')
z87 = me.dynamicsymbols('z87')
intermediates = [
    (UA1, sm.sympify(0.0)),
    (UA1p, sm.sympify(0.0)),
    (UA2, sm.sympify(0.0)),
    (UA2p, sm.sympify(0.0)),
    (z4, -sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3)),
    (z6, sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2)),
    (z7, z4*sm.cos(Q1) - z6*sm.sin(Q1)),
    (z1, -sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2)),
    (z3, sm.sin(Q1)*sm.cos(Q2) + sm.sin(Q2)*sm.cos(Q1)),
    (z9, z4*sm.sin(Q1) + z6*sm.cos(Q1)),
    (z14, L4*z7*(-L3*z3 - L4*z9) + L4*z9*(L3*z1 + L4*z7)),
    (z31, L3*L4*z3*z7/(2*z14)),
    (z32, -L3*L4*z1*z7/(2*z14)),
    (z40, (L3*z1 + L4*z7)/z14),
    (z41, L4**2*z7*z9/(2*z14) - L4*z40*z9/2),
    (z42, L3*L4*z3*z7/z14 + z41),
    (z43, -L4**2*z7**2/(2*z14) + L4*z40*z7/2),
    (z44, -L3*L4*z1*z7/z14 + z43),
    (Q1p, U1),
    (z15, L4*z7*(L2*U1*sm.sin(Q1) + L3*U1*z3 + L4*U1*z9 - UA1) + L4*z9*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2)),
    (U2, z15/z14),
    (Q2p, U2),
    (z17, Q1p*(-sm.sin(Q1)*sm.cos(Q2) - sm.sin(Q2)*sm.cos(Q1)) + Q2p*(-sm.sin(Q1)*sm.cos(Q2) - sm.sin(Q2)*sm.cos(Q1))),
    (z18, Q1p*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2)) + Q2p*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2))),
    (z16, (L3*z1 + L4*z7)*(-L2*U1*sm.sin(Q1) - L3*U1*z3 - L4*U1*z9 + UA1) + (-L3*z3 - L4*z9)*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2)),
    (U3, z16/z14),
    (Q3p, U3),
    (z19, Q2p*(-sm.sin(Q2)*sm.cos(Q3) - sm.sin(Q3)*sm.cos(Q2)) + Q3p*(-sm.sin(Q2)*sm.cos(Q3) - sm.sin(Q3)*sm.cos(Q2))),
    (z20, Q2p*(-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3)) + Q3p*(-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))),
    (z21, Q1p*(-z4*sm.sin(Q1) - z6*sm.cos(Q1)) + z19*sm.cos(Q1) - z20*sm.sin(Q1)),
    (z22, Q1p*(z4*sm.cos(Q1) - z6*sm.sin(Q1)) + z19*sm.sin(Q1) + z20*sm.cos(Q1)),
    (z23, L3*L4*z17*z9 - L3*L4*z18*z7 + z21*(L4**2*z9 + L4*(-L3*z3 - L4*z9)) + z22*(-L4**2*z7 + L4*(L3*z1 + L4*z7))),
    (z66, -L4*z7/z14 + z40),
    (z71, -G*L3*RHO*z32 - G*L4*RHO*z44),
    (z33, L3*L4*z3*z9/(2*z14)),
    (z34, -L3*L4*z1*z9/(2*z14)),
    (z45, (L3*z3 + L4*z9)/z14),
    (z46, L4**2*z9**2/(2*z14) - L4*z45*z9/2),
    (z47, L3*L4*z3*z9/z14 + z46),
    (z48, -L4**2*z7*z9/(2*z14) + L4*z45*z7/2),
    (z49, -L3*L4*z1*z9/z14 + z48),
    (z67, -L4*z9/z14 + z45),
    (z72, -G*L3*RHO*z34 - G*L4*RHO*z49),
    (z28, L4*z7*(L2*sm.sin(Q1) + L3*z3 + L4*z9) + L4*z9*(-L2*sm.cos(Q1) - L3*z1 - L4*z7)),
    (z30, L2*sm.cos(Q1) + L3*z1/2 + L3*z1*z28/(2*z14)),
    (z35, (L3*z1 + L4*z7)*(-L2*sm.sin(Q1) - L3*z3 - L4*z9) + (-L3*z3 - L4*z9)*(-L2*sm.cos(Q1) - L3*z1 - L4*z7)),
    (z38, L4*z7/2 + L4*z28*z7/(2*z14) + L4*z35*z7/(2*z14)),
    (z39, L2*sm.cos(Q1) + L3*z1 + L3*z1*z28/z14 + z38),
    (z50, -G*L2**2*RHO*sm.cos(Q1)/2 - G*L3*RHO*z30 - G*L4*RHO*z39),
    (z29, -L2*sm.sin(Q1) - L3*z3/2 - L3*z28*z3/(2*z14)),
    (z36, -L4*z9/2 - L4*z28*z9/(2*z14) - L4*z35*z9/(2*z14)),
    (z37, -L2*sm.sin(Q1) - L3*z3 - L3*z28*z3/z14 + z36),
    (z65, 1 + z28/z14 + z35/z14),
    (z73, L3**3*RHO/12 + L3**3*RHO*z28/(12*z14)),
    (z74, L4**3*RHO/12 + L4**3*RHO*z28/(12*z14) + L4**3*RHO*z35/(12*z14)),
    (z75, -L2**3*RHO*sm.sin(Q1)**2/4 - L2**3*RHO*sm.cos(Q1)**2/4 - L2**3*RHO/12 - L3*RHO*z29**2 - L3*RHO*z30**2 - L4*RHO*z37**2 - L4*RHO*z39**2 - z65*z74 + z73*(-1 - z28/z14)),
    (z76, -L3*L4*U1*z17*z9 + L3*L4*U1*z18*z7 - L4*UA1p*z7 - L4*UA2p*z9 + Q1p*(L2*L4*U1*z7*sm.cos(Q1) + L2*L4*U1*z9*sm.sin(Q1)) + z21*(-L4**2*U1*z9 + L4*(L2*U1*sm.sin(Q1) + L3*U1*z3 + L4*U1*z9 - UA1)) + z22*(L4**2*U1*z7 + L4*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2))),
    (z77, z76/z14 - z15*z23/z14**2),
    (z78, -L2*Q1p*U1*sm.cos(Q1) - L3*z18*(U1 + U2)/2 - L3*z3*z77/2),
    (z79, -L2*Q1p*U1*sm.sin(Q1) + L3*z1*z77/2 + L3*z17*(U1 + U2)/2),
    (z80, Q1p*(-L2*U1*(L3*z1 + L4*z7)*sm.cos(Q1) + L2*U1*(-L3*z3 - L4*z9)*sm.sin(Q1)) + UA1p*(L3*z1 + L4*z7) + UA2p*(L3*z3 + L4*z9) + z17*(-L3*U1*(-L3*z3 - L4*z9) + L3*(-L2*U1*sm.sin(Q1) - L3*U1*z3 - L4*U1*z9 + UA1)) + z18*(-L3*U1*(L3*z1 + L4*z7) - L3*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2)) + z21*(-L4*U1*(-L3*z3 - L4*z9) + L4*(-L2*U1*sm.sin(Q1) - L3*U1*z3 - L4*U1*z9 + UA1)) + z22*(-L4*U1*(L3*z1 + L4*z7) - L4*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2))),
    (z81, z80/z14 - z16*z23/z14**2),
    (z82, -L4*z22*(U1 + U2 + U3)/2 - L4*z77*z9/2 - L4*z81*z9/2),
    (z83, -L2*Q1p*U1*sm.cos(Q1) - L3*z18*(U1 + U2) - L3*z3*z77 + z82),
    (z84, L4*z21*(U1 + U2 + U3)/2 + L4*z7*z77/2 + L4*z7*z81/2),
    (z85, -L2*Q1p*U1*sm.sin(Q1) + L3*z1*z77 + L3*z17*(U1 + U2) + z84),
    (z86, L4**3*RHO*(z77 + z81)/12),
    (z87, -L3**3*RHO*z77*(1 + z28/z14)/12 - L3*RHO*z29*z78 - L3*RHO*z30*z79 - L4*RHO*z37*z83 - L4*RHO*z39*z85 - z65*z86),
]
# those that need the solved rates (outputs only)
after_solving = [
    (z24, -L3*L4*U1*z17*z9 + L3*L4*U1*z18*z7 - L4*UA1p*z7 - L4*UA2p*z9 + Q1p*(L2*L4*U1*z7*sm.cos(Q1) + L2*L4*U1*z9*sm.sin(Q1)) + U1p*(L4*z7*(L2*sm.sin(Q1) + L3*z3 + L4*z9) + L4*z9*(-L2*sm.cos(Q1) - L3*z1 - L4*z7)) + z21*(-L4**2*U1*z9 + L4*(L2*U1*sm.sin(Q1) + L3*U1*z3 + L4*U1*z9 - UA1)) + z22*(L4**2*U1*z7 + L4*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2))),
    (z25, z24/z14 - z15*z23/z14**2),
    (U2p, z25),
    (z55, -L2*Q1p*U1*sm.cos(Q1) - L3*U2p*z3/2 - L3*z18*(U1 + U2)/2 + U1p*(-L2*sm.sin(Q1) - L3*z3/2)),
    (z56, -L2*Q1p*U1*sm.sin(Q1) + L3*U2p*z1/2 + L3*z17*(U1 + U2)/2 + U1p*(L2*sm.cos(Q1) + L3*z1/2)),
    (z57, L3**3*RHO*(U1p + U2p)/12),
    (z26, Q1p*(-L2*U1*(L3*z1 + L4*z7)*sm.cos(Q1) + L2*U1*(-L3*z3 - L4*z9)*sm.sin(Q1)) + U1p*((L3*z1 + L4*z7)*(-L2*sm.sin(Q1) - L3*z3 - L4*z9) + (-L3*z3 - L4*z9)*(-L2*sm.cos(Q1) - L3*z1 - L4*z7)) + UA1p*(L3*z1 + L4*z7) + UA2p*(L3*z3 + L4*z9) + z17*(-L3*U1*(-L3*z3 - L4*z9) + L3*(-L2*U1*sm.sin(Q1) - L3*U1*z3 - L4*U1*z9 + UA1)) + z18*(-L3*U1*(L3*z1 + L4*z7) - L3*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2)) + z21*(-L4*U1*(-L3*z3 - L4*z9) + L4*(-L2*U1*sm.sin(Q1) - L3*U1*z3 - L4*U1*z9 + UA1)) + z22*(-L4*U1*(L3*z1 + L4*z7) - L4*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2))),
    (z27, z26/z14 - z16*z23/z14**2),
    (U3p, z27),
    (z59, -L4*U1p*z9/2 - L4*U2p*z9/2 - L4*U3p*z9/2 - L4*z22*(U1 + U2 + U3)/2),
    (z61, -L2*Q1p*U1*sm.cos(Q1) - L3*U2p*z3 - L3*z18*(U1 + U2) + U1p*(-L2*sm.sin(Q1) - L3*z3) + z59),
    (z60, L4*U1p*z7/2 + L4*U2p*z7/2 + L4*U3p*z7/2 + L4*z21*(U1 + U2 + U3)/2),
    (z62, -L2*Q1p*U1*sm.sin(Q1) + L3*U2p*z1 + L3*z17*(U1 + U2) + U1p*(L2*sm.cos(Q1) + L3*z1) + z60),
    (z63, L4**3*RHO*(U1p + U2p + U3p)/12),
    (z69, -L3*RHO*z31*z55 - L3*RHO*z32*z56 - L4*RHO*z42*z61 - L4*RHO*z44*z62 + L4*z57*z7/z14 - z63*z66),
    (F1, -z69 - z71),
    (z70, -L3*RHO*z33*z55 - L3*RHO*z34*z56 - L4*RHO*z47*z61 - L4*RHO*z49*z62 + L4*z57*z9/z14 - z63*z67),
    (F2, -z70 - z72),
]

states = [Q1, Q2, Q3, U1]
# d(state)/dt where it is given; None where it is solved (`unknowns`)
rates = [U1, U2, U3, None]
unknowns = [U1p]
unknown_states = [3]
mass_matrix = sm.Matrix(1, 1, [-z75])
forcing = sm.Matrix(1, 1, [z50 + z87])

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
constants = {G: 9.81, L2: 1.0, L3: 2.0, L4: 1.0, RHO: 5.0}
initial_conditions = {Q1: 1.5707963267948966, Q2: 1.5707963267948966, Q3: 1.5707963267948966, U1: 0.5}
# each a number or a function of time; 0 unless given
specified = {}
integration = {'TINITIAL': 0.0, 'TFINAL': 2.0, 'INTEGSTP': 0.01, 'ABSERR': 1e-08, 'RELERR': 1e-07, 'PRINTINT': 1}
# OUTPUT columns: (label, unit, expression in the unit)
outputs = [
    ('T', 'sec', t),
    ('Q1', 'deg', Q1 * 180 / sm.pi),
    ('Q2', 'deg', Q2 * 180 / sm.pi),
    ('Q3', 'deg', Q3 * 180 / sm.pi),
    ('F1', 'N', F1),
    ('F2', 'N', F2),
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
