% SymPy's rolling disc with the contact point tracked (X, Y) and its two no-slip constraints:
% the disc centre's velocity from its position (DT under CONSTRAIN), the dependent speeds
% U4, U5 as outputs.
NEWTONIAN N
FRAMES Y, L
BODIES R
POINTS O, C
CONSTANTS RAD, M, G
VARIABLES Q{3}', X', Y', U{5}'
SIMPROT(N, Y, 3, Q1)
SIMPROT(Y, L, 1, Q2)
SIMPROT(L, R, 2, Q3)
W_R_N> = U1*L1> + U2*L2> + U3*L3>
X' = U4
Y' = U5
V_O_N> = 0>
P_O_C> = X*N1> + Y*N2>
P_C_RO> = RAD*L3>
V_RO_N> = DT(P_O_RO>, N)
MASS R = M
INERTIA R, M*RAD^2/4, M*RAD^2/2, M*RAD^2/4
GRAVITY(-G*Y3>)
V_CR_N> = V_RO_N> + CROSS(W_R_N>, -RAD*L3>)
DEPENDENT[1] = DOT(V_CR_N>, N1>)
DEPENDENT[2] = DOT(V_CR_N>, N2>)
CONSTRAIN(DEPENDENT[U4, U5])
ZERO = FR() + FRSTAR()
KANE()
OUTPUT U4, U5
INPUT RAD = 0.5, M = 2, G = 9.81, Q1 = 0.3, Q2 = 0.2, Q3 = 0.1, X = 0, Y = 0, U1 = 0.4, U2 = 0.5, U3 = 3
