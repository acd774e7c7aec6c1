% pendulum.al
NEWTONIAN N
BODIES A
VARIABLES Q', U'
CONSTANTS L, M, G
SIMPROT(N, A, 3, Q)
Q' = U
W_A_N> = U*N3>
P_NO_AO> = -L*A2>
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 1 m, M = 1 kg, G = 9.81 m/s^2, Q = 30 deg, U = 0
OUTPUT Q, U
