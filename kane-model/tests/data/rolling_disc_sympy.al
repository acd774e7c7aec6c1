% The rolling disc as SymPy's documentation writes it (sympy.physics.mechanics, the rolling
% disc with Kane's method): speeds chosen as the disc's angular velocity in the lean frame L, the
% contact point C the disc's material point at rest (V2PTS from it, no override).
NEWTONIAN N
FRAMES Y, L
BODIES R
POINTS C
CONSTANTS RAD, M, G
VARIABLES Q{3}', U{3}'
SIMPROT(N, Y, 3, Q1)
SIMPROT(Y, L, 1, Q2)
SIMPROT(L, R, 2, Q3)
W_R_N> = U1*L1> + U2*L2> + U3*L3>
V_C_N> = 0>
P_C_RO> = RAD*L3>
V2PTS(N, R, C, RO)
MASS R = M
INERTIA R, M*RAD^2/4, M*RAD^2/2, M*RAD^2/4
GRAVITY(-G*Y3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT RAD = 0.5, M = 2, G = 9.81, Q1 = 0.3, Q2 = 0.2, Q3 = 0.1, U1 = 0.4, U2 = 0.5, U3 = 3
