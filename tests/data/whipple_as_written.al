% The Whipple bicycle of the benchmark (Meijaard, Papadopoulos, Ruina and Schwab 2007) written
% as a bicycle study's Autolev file writes it: the roll and steer torques SPECIFIED and left to the
% code's user, the dependent speeds among the outputs, each wheel's material point at its contact
% by V2PTS (the contact located with another frame's unit vector).
NEWTONIAN N
FRAMES Y, R, FRAME, FORK
BODIES WR, RB, FB, WF
POINTS CR, STEER, CF
% The benchmark's parameters (its Table 1): wheelbase W, trail C, steer axis tilt LAMBDA, wheel
% radii RR and RF, rear body mass centre (XB, ZB), front body mass centre (XH, ZH).
CONSTANTS W, C, LAMBDA, RR, RF, XB, ZB, XH, ZH, G
% The forward speed of straight upright running (m/s): the rear wheel turns at V/RR + U3.
CONSTANTS V
CONSTANTS MR, MB, MH, MF, IRXX, IRYY, IFXX, IFYY
CONSTANTS IBXX, IBYY, IBZZ, IBXZ, IHXX, IHYY, IHZZ, IHXZ
SPECIFIED TPHI, TDELTA
VARIABLES Q{6}', U{6}'
% Moore's geometry from the benchmark's: head tube angle, fork offset, lengths and mass
% centres along and normal to the steer axis.
HTA = PI/2 - LAMBDA
RAKE = -(C*SIN(HTA) - RF*COS(HTA))
FRAMELENGTH = W*SIN(HTA) - (RAKE - (RF - RR)*COS(HTA))
FRAMECG1 = (ZB - RR - XB/SIN(HTA)*COS(HTA))*SIN(HTA)
FRAMECG3 = XB/SIN(HTA) + (ZB - RR - XB/SIN(HTA)*COS(HTA))*COS(HTA)
TA = ZH - RF
TB = W - XH
TC = SQRT(TA^2 + TB^2)
FORKLENGTH = W*COS(HTA) - (RF - RR)*SIN(HTA)
FORKCG3 = RAKE + TC*SIN(PI/2 - HTA - ACOS(TA/TC))
FORKCG1 = TC*COS(PI/2 - HTA - ACOS(TA/TC)) - FORKLENGTH
SIMPROT(N, Y, 3, Q1)
SIMPROT(Y, R, 1, Q2)
SIMPROT(R, FRAME, 2, Q4 + HTA)
SIMPROT(FRAME, RB, 2, -HTA)
SIMPROT(FRAME, WR, 2, Q3)
SIMPROT(FRAME, FORK, 1, Q5)
SIMPROT(FORK, FB, 2, -HTA)
SIMPROT(FORK, WF, 2, Q6)
Q1' = U1
Q2' = U2
Q3' = V/RR + U3
Q4' = U4
Q5' = U5
Q6' = U6
V_CR_N> = 0>
P_CR_WRO> = RR*R3>
V2PTS(N, WR, CR, WRO)
P_WRO_STEER> = FRAMELENGTH*FRAME3>
V2PTS(N, FRAME, WRO, STEER)
P_WRO_RBO> = -FRAMECG1*FRAME1> + FRAMECG3*FRAME3>
V2PTS(N, FRAME, WRO, RBO)
P_STEER_FBO> = -FORKCG1*FORK1> + FORKCG3*FORK3>
V2PTS(N, FORK, STEER, FBO)
P_STEER_WFO> = FORKLENGTH*FORK1> + RAKE*FORK3>
V2PTS(N, FORK, STEER, WFO)
P_WFO_CF> = RF*UNITVEC(DOT(FORK2>, Y3>)*FORK2> - Y3>)
V2PTS(N, WF, WFO, CF)
MASS WR = MR, RB = MB, FB = MH, WF = MF
INERTIA WR, IRXX, IRYY, IRXX
INERTIA WF, IFXX, IFYY, IFXX
INERTIA RB, IBXX, IBYY, IBZZ, 0, 0, IBXZ
INERTIA FB, IHXX, IHYY, IHZZ, 0, 0, IHXZ
GRAVITY(-G*N3>)
TORQUE_RB> = TPHI*Y1>
TORQUE(RB/FB, TDELTA*FORK1>)
% The front wheel touches the ground (which fixes the pitch Q4), rolls without slipping and
% stays on the ground.
CONFIG[1] = DOT(P_CR_CF>, N3>)
DEPENDENT[1] = DOT(V_CF_N>, Y1>)
DEPENDENT[2] = DOT(V_CF_N>, Y2>)
DEPENDENT[3] = DOT(V_CF_N>, Y3>)
CONSTRAIN(DEPENDENT[U1, U4, U6])
ZERO = FR() + FRSTAR()
KANE()
% The energy: kinetic, and the masses' heights above the ground the rear contact is on.
PE = G*(MR*DOT(P_CR_WRO>, N3>) + MB*DOT(P_CR_RBO>, N3>) + MH*DOT(P_CR_FBO>, N3>) + MF*DOT(P_CR_WFO>, N3>))
ENERGY = KE() + PE
OUTPUT Q2, Q5, U1, U4, U6, U1', ENERGY
INPUT W = 1.02, C = 0.08, LAMBDA = 0.3141592653589793, RR = 0.3, RF = 0.35, G = 9.81
INPUT XB = 0.3, ZB = 0.9, XH = 0.9, ZH = 0.7
INPUT MR = 2, MB = 85, MH = 4, MF = 3
INPUT IRXX = 0.0603, IRYY = 0.12, IFXX = 0.1405, IFYY = 0.28
INPUT IBXX = 9.2, IBYY = 11, IBZZ = 2.8, IBXZ = -2.4
INPUT IHXX = 0.05892, IHYY = 0.06, IHZZ = 0.00708, IHXZ = 0.00756
% Straight upright running at the forward speed V: every speed zero.
INPUT V = 0
INPUT Q1 = 0, Q2 = 0, Q3 = 0, Q4 = 0, Q5 = 0, Q6 = 0, U2 = 0, U3 = 0, U5 = 0
INPUT TFINAL = 5, ABSERR = 1e-10, RELERR = 1e-10
