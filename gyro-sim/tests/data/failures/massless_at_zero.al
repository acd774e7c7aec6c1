% A particle at Q1^2/2 along N1, coasting towards Q1 = 0: the mass matrix M*Q1^2 turns singular
% there, which the particle reaches in finite time (Q1*U1 is constant).
NEWTONIAN N
PARTICLES P
POINTS O
CONSTANTS M
VARIABLES Q1', U1'
Q1' = U1
V_O_N> = 0>
P_O_P> = Q1^2/2*N1>
MASS P = M
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, Q1 = -1, U1 = 1, TFINAL = 2, INTEGSTP = 0.1
OUTPUT Q1, U1
