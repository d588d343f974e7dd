"""Numerics of Autolev's CODE commands: compiled functions, integration on Autolev's
print schedule, its input and output files.  Each stage is its own module
(run.py drives them); the package imports none of them, so a stage loads alone."""
