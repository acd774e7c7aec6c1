% A planar triple pendulum of point masses: its mass matrix is a full 3x3 block, so the
% generated solve takes the unrolled LDL^T path (the gimbal's M has a 2x2 and a 1x1 block).
NEWTONIAN N
FRAMES A, B, C
POINTS O
PARTICLES P1, P2, P3
CONSTANTS L{3}, M{3}, G
VARIABLES Q{3}', U{3}'
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
SIMPROT(N, C, 3, Q3)
Q1' = U1
Q2' = U2
Q3' = U3
V_O_N> = 0>
P_O_P1> = L1*A1>
P_P1_P2> = L2*B1>
P_P2_P3> = L3*C1>
V_P1_N> = DT(P_O_P1>, N)
V_P2_N> = DT(P_O_P2>, N)
V_P3_N> = DT(P_O_P3>, N)
MASS P1 = M1, P2 = M2, P3 = M3
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L1 = 1, L2 = 0.8, L3 = 0.6, M1 = 1, M2 = 2, M3 = 0.5, G = 9.81
INPUT Q1 = 0.3, Q2 = -0.2, Q3 = 0.5, U1 = 0, U2 = 0, U3 = 0
