% A dependent speed whose coefficient vanishes at Q1 = 0.
NEWTONIAN N
PARTICLES P, R
POINTS O
CONSTANTS M, K
VARIABLES Q{2}', U{2}'
Q1' = U1
Q2' = U2
V_O_N> = 0>
P_O_P> = Q1*N1>
P_O_R> = Q2*N2>
MASS P = M, R = M
FORCE_P> = -K*Q1*N1>
DEPENDENT[1] = SIN(Q1)*U2 - U1*Q1
CONSTRAIN(DEPENDENT[U2])
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, K = 2, Q1 = 0.5, Q2 = 0, U1 = 0.3
