% A rod hinged at O under a torque T the file leaves SPECIFIED: a scene gives its formula
% ([specified] T = "..."), or the run says it has none.
NEWTONIAN N
BODIES A
POINTS O
CONSTANTS L, M, G, K, C
SPECIFIED T
VARIABLES Q', U'
SIMPROT(N, A, 3, Q)
Q' = U
P_O_AO> = L*A1>
V_O_N> = 0>
V_AO_N> = DT(P_O_AO>, N)
MASS A = M
INERTIA A, 0, M*L^2/12, M*L^2/12
GRAVITY(-G*N2>)
TORQUE_A> = T*N3>
ZERO = FR() + FRSTAR()
KANE()
% Energy without the torque's work: kinetic, gravity's and the spring's.
ENERGY = KE() + M*G*L*SIN(Q) + K*Q^2/2
OUTPUT Q, U, ENERGY
INPUT L = 1, M = 3, G = 9.81, K = 20, C = 0.5, Q = 0.3, U = 0
INPUT TFINAL = 4, ABSERR = 1e-10, RELERR = 1e-10
