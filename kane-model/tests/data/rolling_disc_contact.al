% The rolling disc of rolling_disc.al with its contact force brought into evidence: auxiliary
% speeds UA1, UA2, UA3 translate the disc (its mass centre and its contact point alike), the
% contact force FC1, FC2, FC3 acts at the disc's contact point, and KANE solves for it with
% the rates while the no-slip constraints are solved for the contact speeds U4, U5.
NEWTONIAN N
FRAMES A, B
BODIES D
POINTS O, C, CD
CONSTANTS R, M, G
VARIABLES Q{3}', X', Y', U{5}', UA{3}'
VARIABLES FC{3}
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 1, Q2)
SIMPROT(B, D, 2, Q3)
Q1' = U1
Q2' = U2
Q3' = U3
X' = U4
Y' = U5
V_O_N> = 0>
P_O_C> = X*N1> + Y*N2>
P_C_DO> = R*B3>
V_C_N> = DT(P_O_C>, N)
V_DO_N> = DT(P_O_DO>, N) + UA1*N1> + UA2*N2> + UA3*N3>
A_DO_N> = DT(V_DO_N>, N)
MASS D = M
INERTIA D, M*R^2/4, M*R^2/2, M*R^2/4
GRAVITY(-G*N3>)
% No slip: the disc's material point at the contact has no velocity.
V_CD_N> = V_DO_N> + CROSS(W_D_N>, -R*B3>)
FORCE(CD, FC1*N1> + FC2*N2> + FC3*N3>)
DEPENDENT[1] = DOT(V_CD_N>, N1>)
DEPENDENT[2] = DOT(V_CD_N>, N2>)
AUXILIARY[1] = UA1
AUXILIARY[2] = UA2
AUXILIARY[3] = UA3
CONSTRAIN(AUXILIARY[UA1, UA2, UA3], DEPENDENT[U4, U5])
ZERO = FR() + FRSTAR()
KANE(FC1, FC2, FC3)
% Newton's second law for the disc: what the contact force must equal.
NEWTON1 = M*DOT(A_DO_N>, N1>)
NEWTON2 = M*DOT(A_DO_N>, N2>)
NEWTON3 = M*DOT(A_DO_N>, N3>) + M*G
INPUT R = 0.5, M = 1, G = 9.81
INPUT Q1 = 0.3, Q2 = 0.2, Q3 = 0, X = 0, Y = 0, U1 = 0.5, U2 = 0.1, U3 = 4
OUTPUT Q2, FC1, FC2, FC3, NEWTON1, NEWTON2, NEWTON3
