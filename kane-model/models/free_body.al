% A torque-free rigid body (the EJS "Free Rotation" and "Feynman Plate" models, related models of
% the EJS "Gyroscope", shared seed 000_45039c6968bab2b3.txt): principal moments I1, I2, I3 about
% its mass centre BO, which stays fixed; no forces, no torques. Orientation by Euler parameters
% (Autolev order: E1, E2, E3 the vector part, E4 the scalar; body -> space), speeds the
% body-frame angular velocity components W1, W2, W3, so the equations are Euler's:
% I1 W1' = (I2 - I3) W2 W3, and cyclically.
% I1 = 1, I2 = 2, I3 = 3 by default (the EJS asymmetric body); a thin plate (Feynman's) is
% I1 = I2 = I3/2 with its normal along axis 3.
NEWTONIAN N
BODIES B
POINT O
CONSTANTS I1, I2, I3
VARIABLES E{4}', W{3}'
DIRCOS(N, B, EULER, E1, E2, E3, E4)
W_B_N> = W1*B1> + W2*B2> + W3*B3>
KINDIFFS(N, B, EULER, E1, E2, E3, E4)
V_O_N> = 0>
P_O_BO> = 0>
V2PTS(N, B, O, BO)
MASS B = 1
INERTIA B, I1, I2, I3
ZERO = FR() + FRSTAR()
KANE()
UNITS W1 = RAD/SEC, W2 = RAD/SEC, W3 = RAD/SEC
INPUT I1 = 1, I2 = 2, I3 = 3
INPUT E1 = 0, E2 = 0, E3 = 0, E4 = 1, W1 = 0.01, W2 = 1, W3 = 0.01
OUTPUT E1, E2, E3, E4, W1, W2, W3
% In space axes (N): the angular momentum about the mass centre (constant), and the kinetic
% energy (constant).
L> = MOMENTUM(ANGULAR, BO)
ENERGY = KE()
OUTPUT L>, ENERGY
