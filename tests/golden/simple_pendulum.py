"""Translated from simple_pendulum.al by autolev.

Importing this module builds the model; running it performs the model's
CODE commands with its INPUT values."""
import autolev.runtime as al

if __name__ == "__main__":
    # `python this.py [options]` is `autolev run this.py [options]`: the same
    # messages, files and exit status
    import sys

    from autolev.cli import main
    sys.exit(main(["run", __file__, *sys.argv[1:]]))

model = al.Model('simple_pendulum')
t = model.t

# simple_pendulum.al -- a point mass on a rigid massless rod of length L that
# swings about the Newtonian origin NO.  N1> points down, so THETA = 0 hangs.
# The only motion variable is declared with two primes: THETA' is the speed.

# NEWTONIAN N
N = model.newtonian('N')
NO = N.origin
# FRAMES    A                    % the rod
A = model.frames('A')
# PARTICLES P                    % the bob
P = model.particles('P')
# MOTIONVARIABLES' THETA''
THETA = model.motion_variables('THETA', order=2)
THETAp = al.derivatives(THETA)
# CONSTANTS L, G, M
L, G, M = model.constants('L G M')

# MASS P = M
P.mass = M
# SIMPROT(N, A, 3, THETA)        % W_A_N> = THETA'*N3> follows from this
A.orient_axis(N, N.z, THETA)
# P_NO_P> = L*A1>
P.set_pos(NO, L*A.x)
# V2PTS(N, A, NO, P)
P.v2pt_theory(NO, N, A)

# GRAVITY(G*N1>)
model.gravity(G*N.x)
# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# INPUT L = 1 m, G = 9.81 m/sec^2, M = 1 kg
model.input(L, 1, 'm')
model.input(G, 9.81, 'm/sec^2')
model.input(M, 1, 'kg')
# INPUT THETA = 10 deg, THETA' = 0 rad/sec
model.input(THETA, 10, 'deg')
model.input(THETAp, 0, 'rad/sec')
# INPUT TFINAL = 5, INTEGSTP = 0.01
model.input('TFINAL', 5)
model.input('INTEGSTP', 0.01)

# OUTPUT T sec, THETA deg, THETA' rad/sec
model.output((t, 'T', 'sec'), (THETA, 'THETA', 'deg'), (THETAp, "THETA'", 'rad/sec'))
# CODE DYNAMICS() simple_pendulum.c
model.code('dynamics', 'simple_pendulum.c', zero=ZERO)
