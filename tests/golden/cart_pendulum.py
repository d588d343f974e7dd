"""Translated from cart_pendulum.al by autolev.

Importing this module builds the model; running it performs the model's
CODE commands with its INPUT values."""
import autolev.runtime as al

if __name__ == "__main__":
    # `python this.py [options]` is `autolev run this.py [options]`: the same
    # messages, files and exit status
    import sys

    from autolev.cli import main
    sys.exit(main(["run", __file__, *sys.argv[1:]]))

model = al.Model('cart_pendulum')
t = model.t

# cart_pendulum.al -- a cart on a horizontal track carrying a pendulum.  Only
# second derivatives are declared (MOTIONVARIABLES' X'', TH''): X' and TH' act
# as the generalized speeds, as in Autolev's q''-only models.

# NEWTONIAN N
N = model.newtonian('N')
NO = N.origin
# FRAMES    A                    % the pendulum rod
A = model.frames('A')
# PARTICLES CART, BOB
CART, BOB = model.particles('CART BOB')
# MOTIONVARIABLES' X'', TH''
X, TH = model.motion_variables('X TH', order=2)
Xp, THp = al.derivatives(X, TH)
Xpp = al.derivatives(X, order=2)
# CONSTANTS MC, MB, L, G
MC, MB, L, G = model.constants('MC MB L G')

# MASS CART = MC, BOB = MB
CART.mass = MC
BOB.mass = MB
# SIMPROT(N, A, 3, TH)
A.orient_axis(N, N.z, TH)
# P_NO_CART> = X*N1>
CART.set_pos(NO, X*N.x)
# P_CART_BOB> = -L*A2>
BOB.set_pos(CART, -L*A.y)
# V_CART_N> = X'*N1>
CART.set_vel(N, Xp*N.x)
# A_CART_N> = X''*N1>
CART.set_acc(N, Xpp*N.x)
# V2PTS(N, A, CART, BOB)
BOB.v2pt_theory(CART, N, A)
# A2PTS(N, A, CART, BOB)
BOB.a2pt_theory(CART, N, A)

# GRAVITY(-G*N2>)
model.gravity(-G*N.y)
# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# INPUT MC = 2, MB = 0.5, L = 0.8, G = 9.81
model.input(MC, 2)
model.input(MB, 0.5)
model.input(L, 0.8)
model.input(G, 9.81)
# INPUT X = 0, TH = 30 deg, X' = 0, TH' = 0
model.input(X, 0)
model.input(TH, 30, 'deg')
model.input(Xp, 0)
model.input(THp, 0)
# INPUT TFINAL = 5, INTEGSTP = 0.01
model.input('TFINAL', 5)
model.input('INTEGSTP', 0.01)
# OUTPUT T, X, TH deg
model.output((t, 'T'), (X, 'X'), (TH, 'TH', 'deg'))
# CODE DYNAMICS() cart_pendulum.c
model.code('dynamics', 'cart_pendulum.c', zero=ZERO)
