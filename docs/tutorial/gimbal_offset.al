% gimbal_offset.al: gimbal.al with the rotor moved E up its axle, and gravity
NEWTONIAN A                  % the base, fixed in space; A2 points up
BODIES B, C, D               % the outer gimbal, the inner gimbal, the rotor
POINTS O, P                  % the fixed centre; a point on the rotor's rim

VARIABLES Q{3}', U{3}'       % the angles Q1, Q2, Q3 and the speeds U1, U2, U3
SIMPROT(A, B, -2, Q1)        % B turns about -A2, the vertical, by Q1
SIMPROT(B, C, -1, Q2)        % C turns about -B1 by Q2
SIMPROT(C, D, -2, Q3)        % D spins about -C2, its axle, by Q3

Q1' = U1
Q2' = U2
Q3' = U3

CONSTANTS L                  % the rotor's radius
CONSTANTS E, G               % the rotor's offset; gravity
V_O_A> = 0>                  % O is at rest
P_O_BO> = 0>                 % the three mass centres are at O
P_O_CO> = 0>
P_O_DO> = E*D2>              % the rotor's centre, E up its axle
P_O_P> = L*D1>               % P is on the rim

CONSTANTS M{3}, H{3}, W      % masses; the gimbals' heights H1, H2 and width W; the rotor's thickness H3
MASS B = M1, C = M2, D = M3
I1 = 2/3*M1*(H1*W - W^2)
I2 = 1/6*M1*H1^2 - 1/6*M1*(H1 - W)^2
INERTIA B, I1, I1, I2        % moments about B1, B2, B3
J1 = 2/3*M2*(H2*W - W^2)
J2 = 1/6*M2*H2^2 - 1/6*M2*(H2 - W)^2
INERTIA C, J1, J1, J2
K1 = 1/2*M3*L^2              % the rotor about its axle D2
K2 = 1/4*M3*L^2 + 1/12*M3*H3^2
INERTIA D, K2, K1, K2

CONSTANTS Y, Z               % torques on the gimbals
TORQUE_B> = Y*A2>            % on B, about the vertical
TORQUE_C> = Z*B1>            % on C, about its pivots
GRAVITY(-G*A2>)              % weight, along -A2

ZERO = FR() + FRSTAR()
KANE()

UNITS Q1 = DEG, Q2 = DEG, Q3 = DEG, U1 = RAD/S, U2 = RAD/S, U3 = RAD/S
INPUT L = 0.3 m, W = 0.025 m, H1 = 0.6 m, H2 = 0.5 m, H3 = 0.4 m
INPUT M1 = 2 kg, M2 = 2 kg, M3 = 50 kg, Y = 0 N*m, Z = 0 N*m
INPUT E = 0.1 m, G = 9.81 m/s^2
INPUT Q1 = 0 deg, Q2 = 0 deg, Q3 = 0 deg, U1 = 0 rad/s, U2 = 0 rad/s, U3 = 100 rad/s
INPUT TFINAL = 5 s, INTEGSTP = 0.05 s, ABSERR = 1e-8, RELERR = 1e-8
AP = MAG(A_P_A>)             % |a_P|, the paper's right-hand figures
UNITS AP = M/S^2
OUTPUT Q1, Q2, Q3, U1, U2, U3, AP
