% A particle pulled by LN(Q1) towards Q1 = 0, which it reaches: past it the logarithm's argument is
% negative.
NEWTONIAN N
PARTICLES P
POINTS O
CONSTANTS M
VARIABLES Q1', U1'
Q1' = U1
V_O_N> = 0>
P_O_P> = Q1*N1>
MASS P = M
FORCE_P> = -(2 + LN(Q1))*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, Q1 = 1, U1 = -1, TFINAL = 3, INTEGSTP = 0.1
OUTPUT Q1, U1
