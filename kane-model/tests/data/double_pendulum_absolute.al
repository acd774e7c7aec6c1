% A double pendulum of two particles, each link oriented from N (absolute angles).
NEWTONIAN N
FRAMES A, B
POINTS O, P, R
PARTICLES PA, PB
VARIABLES Q1', Q2', U1', U2'
CONSTANTS L1, L2, M1, M2, G
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
Q1' = U1
Q2' = U2
W_A_N> = U1*N3>
W_B_N> = U2*N3>
P_O_PA> = L1*A1>
P_PA_PB> = L2*B1>
V_O_N> = 0>
V_PA_N> = DT(P_O_PA>, N)
V_PB_N> = DT(P_O_PB>, N)
MASS PA = M1, PB = M2
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L1 = 1, L2 = 1.2, M1 = 1, M2 = 2, G = 9.81, Q1 = 0.3, Q2 = 0.2, U1 = 0, U2 = 0
