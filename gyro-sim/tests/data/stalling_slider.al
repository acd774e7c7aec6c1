% A slider pushed towards Q1 = pi/2, where the constraint cos(Q1)*U2 = U1 loses rank: the
% slaved particles take ever more of the energy, and the slider only creeps towards it.
NEWTONIAN N
PARTICLES P, R, S
POINTS O
CONSTANTS M, F
VARIABLES Q{3}', U{3}'
Q1' = U1
Q2' = U2
Q3' = U3
V_O_N> = 0>
P_O_P> = Q1*N1>
P_O_R> = Q2*N2>
P_O_S> = Q3*N3>
MASS P = M, R = M, S = M
FORCE_P> = F*N1>
DEPENDENT[1] = COS(Q1)*U2 - U1
DEPENDENT[2] = U3 - U2
CONSTRAIN(DEPENDENT[U2, U3])
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, F = 1, Q1 = 0, Q2 = 0, Q3 = 0, U1 = 0
OUTPUT Q1, U1
