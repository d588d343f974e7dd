"""Translated from euler_parameters_body.al by autolev.

Importing this module builds the model; running it performs the model's
CODE commands with its INPUT values."""
import autolev.runtime as al

if __name__ == "__main__":
    # `python this.py [options]` is `autolev run this.py [options]`: the same
    # messages, files and exit status
    import sys

    from autolev.cli import main
    sys.exit(main(["run", __file__, *sys.argv[1:]]))

model = al.Model('euler_parameters_body')
t = model.t

# euler_parameters_body.al -- a rigid body turning about its fixed mass center
# under a constant torque.  Its orientation in N is given by Euler parameters
# (E4 the scalar part); the speeds are its angular velocity measure numbers in B.

# NEWTONIAN N
N = model.newtonian('N')
NO = N.origin
# BODIES    B
B = model.bodies('B')
BO = B.masscenter
# VARIABLES E{4}'
E1, E2, E3, E4 = model.variables('E1 E2 E3 E4', order=1)
# MOTIONVARIABLES' U{3}'
U1, U2, U3 = model.motion_variables('U1 U2 U3', order=1)
# CONSTANTS M, I1, I2, I3, T1, T2, T3
M, I1, I2, I3, T1, T2, T3 = model.constants('M I1 I2 I3 T1 T2 T3')

# MASS B = M
B.mass = M
# INERTIA B, I1, I2, I3
B.set_inertia(I1, I2, I3)

# DIRCOS(N, B, EULER, E1, E2, E3, E4)
B.orient_euler_parameters(N, E1, E2, E3, E4)
# W_B_N> = U1*B1> + U2*B2> + U3*B3>
B.set_ang_vel(N, U1*B.x + U2*B.y + U3*B.z)
# KINDIFFS(N, B, EULER, E1, E2, E3, E4)
model.kindiffs(N, B, 'EULER', E1, E2, E3, E4)

# P_NO_BO> = 0>
BO.set_pos(NO, al.ZERO)
# V_BO_N> = 0>
BO.set_vel(N, al.ZERO)

# TORQUE(B, T1*B1> + T2*B2> + T3*B3>)
model.torque(B, T1*B.x + T2*B.y + T3*B.z)
# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# INPUT M = 1, I1 = 0.2, I2 = 0.3, I3 = 0.45, T1 = 0, T2 = 0.01, T3 = 0
model.input(M, 1)
model.input(I1, 0.2)
model.input(I2, 0.3)
model.input(I3, 0.45)
model.input(T1, 0)
model.input(T2, 0.01)
model.input(T3, 0)
# INPUT E1 = 0, E2 = 0, E3 = 0, E4 = 1
model.input(E1, 0)
model.input(E2, 0)
model.input(E3, 0)
model.input(E4, 1)
# INPUT U1 = 0.1, U2 = 2, U3 = 0.05
model.input(U1, 0.1)
model.input(U2, 2)
model.input(U3, 0.05)
# INPUT TFINAL = 10, INTEGSTP = 0.05
model.input('TFINAL', 10)
model.input('INTEGSTP', 0.05)
# OUTPUT T, E1, E2, E3, E4, U1, U2, U3
model.output(
    (t, 'T'),
    (E1, 'E1'),
    (E2, 'E2'),
    (E3, 'E3'),
    (E4, 'E4'),
    (U1, 'U1'),
    (U2, 'U2'),
    (U3, 'U3'),
)
# CODE DYNAMICS() euler_parameters_body.c
model.code('dynamics', 'euler_parameters_body.c', zero=ZERO)
