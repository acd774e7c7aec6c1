% A particle pushed by 1/(T - 1): the force has a pole at T = 1, where the steps collapse.
NEWTONIAN N
PARTICLES P
POINTS O
CONSTANTS M
VARIABLES Q1', U1'
Q1' = U1
V_O_N> = 0>
P_O_P> = Q1*N1>
MASS P = M
FORCE_P> = 1/(T - 1)*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, Q1 = 0, U1 = 0, TFINAL = 2, INTEGSTP = 0.1
OUTPUT Q1, U1
