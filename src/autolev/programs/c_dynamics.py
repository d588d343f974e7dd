"""A CODE DYNAMICS() program in C, in the layout of Autolev 4.1's: main reads the
constants, the initial values and the integration parameters (three groups of the .in
file), evaluates the constants once and integrates with Kutta-Merson, calling
output() every PRINTINT steps; eqns1 gives the derivatives (the unknown ones from
M x = F, solved at each call); kutta, solve, readf, pgets and writef follow."""
from __future__ import annotations

from ..runtime import symbols as S
from ..runtime.printer import CPrinter
from .c import (KEYWORDS, LIBRARY_NAMES, OWN_NAMES, READING_AND_WRITING, READING_PROTOTYPES,
                SOLVE, _lines, banner, by_name, encoded_declarations, farewell,
                headings_and_units, opening, output_lines, wrap)
from .plan import (DynamicsPlan, dynamics_names, input_file_name, print_dynamics,
                   program_name, rename_clashes)

# a DYNAMICS program's own names besides, as spelt: kutta's and solve's, eqns1's
# arguments, main's integration parameters and counters, the macro NUMY
_DYNAMICS_NAMES = frozenset("""
kutta solve COEF RHS SOL VAR VARp boundary T TINITIAL TFINAL INTEGSTP iprint printint
_printint abserr relerr NUMY
""".split())


class CDynamicsProgram:
    """The text of one DynamicsPlan's C program."""

    def __init__(self, plan: DynamicsPlan):
        rename_clashes(plan, KEYWORDS | OWN_NAMES | LIBRARY_NAMES | _DYNAMICS_NAMES, "C")
        self.plan = plan
        self.name = program_name(plan.filename)
        self.stem = self.name.rpartition(".")[0] or self.name
        self.nfiles = len(plan.files)
        self.n, self.m = len(plan.states), len(plan.unknowns)
        self.names = dynamics_names(plan, plan.name_of)
        self.z_size = 0

    def text(self) -> str:
        p = self.plan
        parts = print_dynamics(p, self.names, CPrinter, lambda k: f"z[{k}]", p.name_of)
        self.z_size = parts.z_size
        kutta = [f"#define  NUMY      {self.n}        /* the states kutta integrates */"]
        lines = (self._top() + self._main(_lines(parts.constants, p.sources)) + ["", ""]
                 + self._eqns1(_lines(parts.equations, p.sources), parts) + ["", ""]
                 + self._output(_lines(parts.outputs, p.sources), parts.outputs.values)
                 + ["", ""] + kutta + _KUTTA + ["", ""] + SOLVE + ["", ""]
                 + READING_AND_WRITING)
        return "\n".join(lines) + "\n"

    # -- text -----------------------------------------------------------------------
    def _top(self) -> list[str]:
        p = self.plan
        lines = banner(self.name) + [
            "void     eqns1     (double T, double VAR[], double VARp[], char boundary);",
            "void     output    (FILE *Fptr[], double T);",
            "int      kutta     (void(*eqns)(double, double*, double*, char),",
            "                    int numy, double y[], double *t, double integstp,",
            "                    double abserr, double relerr, char com);",
            "int      solve     (int n, double *coef, double *rhs, double *x);"]
        lines += READING_PROTOTYPES
        derivatives = p.derivatives
        algebraic = derivatives + [s for s in by_name(p.named) if s not in derivatives]
        groups = (p.constants, by_name(p.specified), p.states, algebraic)
        for group in groups:
            if group:
                lines += wrap("double   ", ",".join(p.name_of(s) for s in group))
        solving = ([f"COEF[{self.m}][{self.m}]", f"RHS[{self.m}]", f"SOL[{self.m}]"]
                   if self.m > 1 else [])
        declared = {p.name_of(s) for group in groups for s in group}
        return lines + encoded_declarations(p.encoded, self.z_size, solving, declared) + [""]

    def _main(self, statements: list) -> list[str]:
        p = self.plan
        infile = input_file_name(p.filename)
        lines = ["/* ................................ MAIN ............................. */",
                 "int      main         (void)", "{",
                 f"FILE     *Fptr[{self.nfiles + 1}];",
                 "int      iprint, printint, iloop;",
                 "double   T,TINITIAL,TFINAL,INTEGSTP,abserr,relerr,_printint;",
                 f"double   VAR[{self.n}];", ""]
        lines += opening(infile, self.stem, self.nfiles)
        lines.append("/* Read values of constants from input file */")
        if p.constants:
            lines += wrap("readf(Fptr[0],", ",".join("&" + p.name_of(s) for s in p.constants),
                          ",NULL);")
        else:
            lines.append("pgets(Fptr[0], NULL);")
        lines += ["", "/* Read the initial value of each variable from input file */"]
        lines += wrap("readf(Fptr[0],", ",".join("&" + p.name_of(s) for s in p.states),
                      ",NULL);")
        lines += ["", "/* Read integration parameters from input file */",
                  "readf(Fptr[0],&TINITIAL,&TFINAL,&INTEGSTP,&_printint,&abserr,&relerr,"
                  "NULL);",
                  "printint = (int)_printint;", ""]
        lines += headings_and_units(self.stem, p.files,
                                    [p.name_of(s) for s in p.degree_inputs])
        lines += ["", "/* Evaluate constants */"] + statements
        lines += ["", "/* Initialize time, print counter, variables array for integrator */",
                  "  T      = TINITIAL;", "  iprint = 0;"]
        lines += [f"  VAR[{k}] = {p.name_of(x)};" for k, x in enumerate(p.states)]
        lines += ["", "/* Initalize numerical integrator, with call to eqns1 at T=TINITIAL */",
                  f"kutta(eqns1, {self.n}, VAR, &T, INTEGSTP, abserr, relerr, 0);", "",
                  "/* Numerically integrate; print results */",
                  "while(1)", "  {",
                  "  if( TFINAL >= TINITIAL && T + 0.01*INTEGSTP >= TFINAL ) iprint = -7;",
                  "  if( TFINAL <= TINITIAL && T + 0.01*INTEGSTP <= TFINAL ) iprint = -7;",
                  "  if( iprint <= 0 )", "    {",
                  "    output(Fptr, T);",
                  "    if( iprint == -7 ) break;",
                  "    iprint = printint;", "    }",
                  f"  if( !kutta(eqns1, {self.n}, VAR, &T, INTEGSTP, abserr, relerr, 2) )",
                  "    {",
                  "    output(Fptr, T);",
                  f"    for(iloop = 0; iloop <= {self.nfiles}; iloop++)",
                  '      fputs("\\n\\tError: Numerical integration failed to converge\\n",'
                  " iloop ? Fptr[iloop] : stdout);",
                  "    break;", "    }",
                  "  iprint--;", "  }", ""]
        return lines + farewell(infile, self.stem, self.nfiles)

    def _eqns1(self, statements: list, parts) -> list[str]:
        p = self.plan
        lines = ["/* ................................ EQNS1 ............................. */",
                 "void     eqns1        (double T, double VAR[], double VARp[], char "
                 "boundary)", "{", "(void)T; (void)boundary;", "",
                 "/* Update variables after integration step */"]
        lines += [f"  {p.name_of(x)} = VAR[{k}];" for k, x in enumerate(p.states)]
        if p.specified:
            lines += ["", "/* Quantities to be specified */"]
            lines += [f"  {p.name_of(s)} = 0;" for s in p.specified]
        lines += [""] + statements
        for target, text in parts.rates:
            lines += wrap(f"  {target} = ", text)
        mass, forcing = parts.mass, parts.forcing
        if self.m == 1:
            lines += wrap(f"  {p.name_of(p.unknowns[0])} = ", f"({forcing[0]})/({mass[0]})")
        elif self.m > 1:
            for i in range(self.m):
                for j in range(self.m):
                    lines += wrap(f"  COEF[{i}][{j}] = ", mass[i * self.m + j])
                lines += wrap(f"  RHS[{i}] = ", forcing[i])
            lines += [f"  if( solve({self.m}, COEF[0], RHS, SOL) )",
                      '    {printf("\\n The mass matrix is singular at T = %g\\n", T);'
                      "  exit(1);}"]
            lines += [f"  {p.name_of(u)} = SOL[{i}];" for i, u in enumerate(p.unknowns)]
        lines += ["", "/* Update derivative array prior to integration step */"]
        lines += [f"  VARp[{k}] = {p.name_of(S.derivative(x))};"
                  for k, x in enumerate(p.states)]
        return lines + ["}"]

    def _output(self, statements: list, values: list) -> list[str]:
        p = self.plan
        lines = ["/* ................................ OUTPUT ............................. */",
                 "void     output (FILE *Fptr[], double T)", "{", "(void)T;"]
        if not p.files:
            lines.append("(void)Fptr;")
        lines += ["", "/* Evaluate output quantities */"] + statements
        lines += ["", "/* Write output to screen and to output file(s) */"]
        lines += output_lines(p.files, p.encoded, values) + [""]
        lines += [f"  Encode[{k}] = 0.0;" for k in range(len(p.encoded))]
        return lines + ["", "}"]


# Autolev's integrator (Kutta-Merson, the error test and step control of its programs:
# docs/language.md), written for autolev
_KUTTA = r"""
/* ................................ KUTTA ............................. */
/* Kutta-Merson with a variable step (L. Fox, 1962): advances *t by integstp.  com 0:
 * evaluate the derivatives at the start; 2: a step, the derivatives recomputed at the
 * start of every internal step.  A step is halved while, for some y, the error
 * estimate is at least both relerr*|y| and abserr (at most 20 times: then it fails
 * and returns 0), and doubled when the estimate is 64 times smaller. */
int      kutta (void(*eqns)(double, double*, double*, char), int numy, double y[],
                double *t, double integstp, double abserr, double relerr, char com)
{
static double f0[NUMY], f1[NUMY], f2[NUMY], y1[NUMY], y2[NUMY];
static int    numcuts = 20;
static double hc = 0;
double        h, h2, h3, h6, h8, tt, tfinal;
int           i, bad, twice;

if( numy > NUMY )
  {printf("\n kutta: at most %d states\n", NUMY);  return 0;}
if( com == 0 ) { eqns(*t, y, f0, 1);  return 1; }
if( integstp == 0 ) { printf("\n kutta: the integration step is 0\n");  return 0; }
if( hc * integstp < 0 ) hc = -hc;
if( hc == 0 ) hc = integstp;
h      = hc;
tt     = *t + h;
tfinal = *t + integstp;
*t     = tfinal;
eqns(tt - h, y, f0, 1);
while( tt + h != tt )
  {
  h2 = h * 0.5;  h3 = h / 3.0;  h6 = h / 6.0;  h8 = h * 0.125;
  for( i = 0; i < numy; i++ ) y1[i] = y[i] + h3 * f0[i];
  eqns(tt - 2.0 * h3, y1, f1, 0);
  for( i = 0; i < numy; i++ ) y1[i] = y[i] + h6 * (f0[i] + f1[i]);
  eqns(tt - 2.0 * h3, y1, f1, 0);
  for( i = 0; i < numy; i++ ) y1[i] = y[i] + h8 * (f0[i] + 3.0 * f1[i]);
  eqns(tt - h2, y1, f2, 0);
  for( i = 0; i < numy; i++ ) y1[i] = y[i] + h2 * (f0[i] - 3.0 * f1[i] + 4.0 * f2[i]);
  eqns(tt, y1, f1, 0);
  for( i = 0; i < numy; i++ ) y2[i] = y[i] + h6 * (f0[i] + 4.0 * f2[i] + f1[i]);
  bad = 0;  twice = 1;
  for( i = 0; i < numy; i++ )
    {
    double error = fabs(y1[i] - y2[i]) * 0.2, test = fabs(y1[i]) * relerr;
    if( error >= test && error >= abserr ) bad = 1;
    if( 64.0 * error > test && 64.0 * error > abserr ) twice = 0;
    }
  if( bad )
    {
    hc = h = h2;
    tt -= h2;
    if( --numcuts >= 0 ) continue;
    printf("\n THE STEPSIZE HAS BEEN HALVED TOO MANY TIMES; T = %15.8E\n", tt - h);
    *t = tt - h;
    eqns(*t, y, f0, 0);
    return 0;
    }
  for( i = 0; i < numy; i++ ) y[i] = y2[i];
  if( twice && fabs(h + h) <= fabs(integstp) && fabs(tt + h + h) <= fabs(tfinal) )
    { hc = h = h + h;  numcuts++; }
  if( tt == tfinal ) { eqns(tfinal, y, f0, 2);  return 1; }
  tt += h;
  if( (h > 0 && tt > tfinal - 0.1 * h) || (h < 0 && tt < tfinal - 0.1 * h) )
    { h = tfinal - (tt - h);  tt = tfinal; }
  eqns(tt - h, y, f0, 1);
  }
printf("\n THE STEPSIZE OF %15.7E IS TOO SMALL RELATIVE TO THE TERMINAL TIME OF\n"
       " %15.7E.  INTEGRATION HALTED.\n", h, tt);
return 0;
}""".splitlines()[1:]


def write_c_dynamics(plan: DynamicsPlan) -> dict:
    """{file name: text}: the program and the .in file it reads."""
    return {plan.filename: CDynamicsProgram(plan).text(),
            input_file_name(plan.filename): plan.input_text}
