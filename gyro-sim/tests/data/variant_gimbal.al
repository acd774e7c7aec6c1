% A variant of the paper's gimbal (kane-model/models/gimbal_gyroscope.al) as a user would write
% it outside the project: the rotor's mass centre 5 cm along its axis, gravity on the rotor,
% the rotor's axis flipped (SIMPROT about +C2). Lines 23-25 (A_BO_A> = 0> ...) are dropped:
% with the offset they would contradict the positions (kane check says so).
% The 3-DOF gimballed gyroscope of "Dynamical Multi-body Gyroscopic Motion Simulation"
% (shared seed 001_d80063f62583a37b.txt): the paper's 44 Autolev commands, transcribed.
% Line numbers below are the paper's. Its text came through OCR; every fix is noted.
%
% Interpretation notes:
% - SIMPROT with a negative axis is a rotation about the negative of that axis.
% - Lines 23-25 set A_BO_A>, A_CO_A>, A_DO_A> to 0> but the paper never places BO, CO, DO.
%   Zero acceleration for all motions means the mass centres stay at the fixed point O, so this
%   file places them there (P_O_BO> = 0> etc., added after line 25). Kane's method needs their
%   velocities, which then follow from V_O_A> = 0>.
% - Line 29 (A_O_A> = 0>) is kept; it agrees with V_O_A> = 0>.
% - Lines 36-38 give units; "SFC" and "DFG" are OCR for SEC and DEG. Angles are input and
%   reported in degrees and integrated in radians.
% - Line 42's INTFGSTP, ABSFRR, RFLFRR and 1.0F-07 are OCR for INTEGSTP, ABSERR, RELERR, 1.0E-07.
% - The script's own INPUT case is Y = 0, Z = 10, U3 = 10; the paper's Trial 1 text says a
%   torque on B (Y = 10, Z = 0), Trial 2 both (Y = Z = 10), Trial 3 Trial 2 with U3 = 100.

NEWTONIAN A                                   % 1
POINTS P, O                                   % 2  ("POINT P,0": the letter O, not zero)
BODIES B, C, D                                % 3
CONSTANTS M{3}, H{3}, L, W, Y, Z, OFF, G              % 4
I1 = 2/3*M1*(H1*W - W^2)                      % 5  ("11=" is I1)
I2 = 1/6*M1*(H1^2) - 1/6*M1*(H1 - W)^2        % 6  ("12=" is I2)
I_B_BO>> = I1*B1>*B1> + I1*B2>*B2> + I2*B3>*B3>   % 7
J1 = 2/3*M2*(H2*W - W^2)                      % 8
J2 = 1/6*M2*(H2^2) - 1/6*M2*(H2 - W)^2        % 9
I_C_CO>> = J1*C1>*C1> + J1*C2>*C2> + J2*C3>*C3>   % 10 ("1 C CO>>" is I_C_CO>>)
K1 = 1/2*M3*L^2                               % 11 ("Kl=l/2" is K1=1/2)
K2 = 1/4*M3*L^2 + 1/12*M3*H3^2                % 12
I_D_DO>> = K2*D1>*D1> + K1*D2>*D2> + K2*D3>*D3>   % 13
VARIABLES Q{3}', U{3}'                        % 14
SIMPROT(A, B, -2, Q1)                         % 15 ("SIMPR0T", "ql")
SIMPROT(B, C, -1, Q2)                         % 16 ("-l")
SIMPROT(C, D, 2, Q3)     % variant: rotor axis flipped                         % 17
Q1' = U1                                      % 18 (OCR dropped the prime)
Q2' = U2                                      % 19
Q3' = U3                                      % 20
P_O_P> = L*D1>                                % 21 ("P_0_P>")
V_O_A> = 0>                                   % 22
                                  % 23
                                  % 24
                                  % 25
P_O_BO> = 0>                                  % added: see the notes above
P_O_CO> = 0>                                  % added
P_O_DO> = OFF*D2>         % variant: rotor offset along its axis                                  % added
V2PTS(A, D, O, P)                             % 26
EXPRESS(V_P_A>, A)                            % 27
EXPAND(V_P_A>)                                % 28
A_O_A> = 0>                                   % 29
A_P_A> = EXPRESS(A_P_A>, A)                   % 30
MASS B = M1, C = M2, D = M3                   % 31
TORQUE_B> = Y*A2>                             % 32 ("T0RQUE")
TORQUE_C> = Z*B1>
FORCE_DO> = -M3*G*A2>     % variant: gravity on the rotor                             % 33
ZERO = FR() + FRSTAR()                        % 34
KANE()                                        % 35
UNITS M1 = KG, M2 = KG, M3 = KG, T = SEC, H1 = M, H2 = M, H3 = M      % 36
UNITS OFF = M, G = M/SEC^2, L = M, W = M, Y = N*M, Z = N*M                                   % 37
UNITS Q1 = DEG, Q2 = DEG, Q3 = DEG, U1 = RAD/SEC, U2 = RAD/SEC, U3 = RAD/SEC   % 38
INPUT L = .3, W = .025, H1 = .6, H2 = .5, H3 = .4                      % 39
INPUT M1 = 2, M2 = 2, M3 = 50, Y = 0, Z = 10, OFF = 0.05, G = 9.81                           % 40
INPUT Q1 = 0, Q2 = 0, Q3 = 0, U1 = 0, U2 = 0, U3 = 10                  % 41
INPUT TFINAL = 5, INTEGSTP = .05, ABSERR = 1.0E-07, RELERR = 1.0E-07   % 42
OUTPUT T, Q1, Q2, Q3, U1, U2, U3                                       % 43
AP = MAG(A_P_A>)          % added: |a_P|, which the paper plots on the right of Figures 3-5
UNITS AP = M/SEC^2        % added
OUTPUT AP                 % added
OUTPUT A_B, A_C, A_D      % added: the frames' direction cosines (A_D_ij = a_i . d_j), for the 3-D view
CODE DYNAMICS() PHASE3.M, SUBS                                         % 44
