% The double pendulum of prescribed_elbow.al with a free elbow Q2 driven by a constant torque T2.
NEWTONIAN N
BODIES A, B
POINTS O, E
VARIABLES Q{2}', U{2}'
CONSTANTS L, M, G, T2
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
Q1' = U1
Q2' = U2
P_O_AO> = L/2*A1>
P_O_E> = L*A1>
P_E_BO> = L/2*B1>
V_O_N> = 0>
V2PTS(N, A, O, AO)
V2PTS(N, A, O, E)
V2PTS(N, B, E, BO)
MASS A = M, B = M
INERTIA A, 0, M*L^2/12, M*L^2/12
INERTIA B, 0, M*L^2/12, M*L^2/12
GRAVITY(-G*N2>)
TORQUE(A/B, T2*A3>)
KANE()
INPUT L = 1, M = 1, G = 9.81, T2 = 0, Q1 = 0.3, U1 = 0
