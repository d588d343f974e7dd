"""The engine: what computes a prepared CODE command and writes its files, with no
model, no translator and no sympy (a warm run executes its run plan with this alone).

It integrates (Autolev's Kutta-Merson, the compiled loop and its C, scipy's methods),
evaluates and solves (ALGEBRAIC, NONLINEAR, sweeps), solves the mass matrix, writes the
output files (the one writer: whole or not at all), keeps the caches (the private
folder, run plans, the digests of what a command read and the request it answers) and
linearizations' numbers.  runtime/numerics turns a model's symbolic equations into its
input: compiled functions, numbers, names.  Nothing here imports anything outside this
package (tests/test_architecture.py).
"""
