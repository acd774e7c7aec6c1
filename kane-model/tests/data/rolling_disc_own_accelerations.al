% A thin disc rolling without slipping on the plane N1-N2: yaw Q1, lean Q2, spin Q3, and the
% contact point at (X, Y). The contact point's speeds U4, U5 follow from the no-slip
% constraints, solved numerically wherever the equations are evaluated.
NEWTONIAN N
FRAMES A, B
BODIES D
POINTS O, C
CONSTANTS R, M, G
VARIABLES Q{3}', X', Y', U{5}'
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
V_DO_N> = DT(P_O_DO>, N)
MASS D = M
INERTIA D, M*R^2/4, M*R^2/2, M*R^2/4
GRAVITY(-G*N3>)
% No slip: the disc's material point at the contact has no velocity.
V_CD_N> = V_DO_N> + CROSS(W_D_N>, -R*B3>)
DEPENDENT[1] = DOT(V_CD_N>, N1>)
DEPENDENT[2] = DOT(V_CD_N>, N2>)
CONSTRAIN(DEPENDENT[U4, U5])
% The file writes its own accelerations, in the dependent speeds and their rates.
A_DO_N> = DT(V_DO_N>, N)
ALF_D_N> = DT(W_D_N>, N)
ZERO = FR() + FRSTAR()
KANE()
INPUT R = 0.5, M = 1, G = 9.81
INPUT Q1 = 0.3, Q2 = 0, Q3 = 0, X = 0, Y = 0, U1 = 0.5, U2 = 0.1, U3 = 4
