% A double pendulum of two uniform rods hinged at O, swinging in the N1-N2 plane under gravity
% along -N2: the default view's test model (frames A, B at their mass centres; points O, P, AO,
% BO joined up).
NEWTONIAN N
BODIES A, B
POINTS O, P
CONSTANTS L, G, M
VARIABLES Q{2}', U{2}'
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
Q1' = U1
Q2' = U2
P_O_AO> = L/2*A1>
P_O_P> = L*A1>
P_P_BO> = L/2*B1>
V_O_N> = 0>
V2PTS(N, A, O, AO)
V2PTS(N, A, O, P)
V2PTS(N, B, P, BO)
MASS A = M, B = M
INERTIA A, M*L^2/200, M*L^2/12, M*L^2/12
INERTIA B, M*L^2/200, M*L^2/12, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
OUTPUT Q1, Q2
INPUT L = 1, G = 9.81, M = 1, Q1 = -1.2, Q2 = 0.8, U1 = 0, U2 = 0
INPUT TFINAL = 3, INTEGSTP = 0.01, ABSERR = 1e-10, RELERR = 1e-10
