% A double pendulum whose elbow follows a prescribed angle EA(t): the shoulder swings freely and
% the elbow torque ETOR that makes the prescribed motion happen is solved for, as sprinting
% models drive a swing leg: an auxiliary speed U2 in the elbow, KANE(ETOR).
NEWTONIAN N
BODIES A, B
POINTS O, E
VARIABLES Q1', U{2}'
VARIABLES ETOR
SPECIFIED EA''
CONSTANTS L, M, G, AMP, W
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, EA)
Q1' = U1
W_A_N> = U1*N3>
W_B_A> = EA'*A3> + U2*A3>
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
TORQUE(A/B, ETOR*A3>)
EA = AMP*SIN(W*T)
% The energy and the power the elbow torque puts in (the shoulder is free).
ENERGY = KE() + M*G*(DOT(P_O_AO>, N2>) + DOT(P_O_BO>, N2>))
POWER = ETOR*EA'
AUXILIARY[1] = U2
CONSTRAIN(AUXILIARY[U2])
ZERO = FR() + FRSTAR()
KANE(ETOR)
INPUT L = 1, M = 1, G = 9.81, AMP = 0.5, W = 2, Q1 = 0.3, U1 = 0
OUTPUT Q1, U1, ETOR, ENERGY, POWER
