% A planar four-bar linkage closed into a loop: crank A (angle Q1) pinned at O, coupler B
% (absolute angle Q2) pinned to the crank's tip, rocker C (absolute angle Q3) pinned at D on the
% ground. The loop closes at the coupler's far end: two configuration constraints, so Q2, Q3
% and their speeds are dependent on the crank.
NEWTONIAN N
BODIES A, B, C
POINTS O, D, AB, BC
CONSTANTS LA, LB, LC, LD, MA, MB, MC, G
VARIABLES Q{3}', U{3}'
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
SIMPROT(N, C, 3, Q3)
Q1' = U1
Q2' = U2
Q3' = U3
P_O_D> = LD*N1>
P_O_AO> = LA/2*A1>
P_O_AB> = LA*A1>
P_AB_BO> = LB/2*B1>
P_AB_BC> = LB*B1>
P_D_CO> = LC/2*C1>
V_O_N> = 0>
V_D_N> = 0>
V_AO_N> = DT(P_O_AO>, N)
V_AB_N> = DT(P_O_AB>, N)
V_BO_N> = DT(P_O_BO>, N)
V_CO_N> = DT(P_O_CO>, N)
MASS A = MA, B = MB, C = MC
INERTIA A, 0, MA*LA^2/12, MA*LA^2/12
INERTIA B, 0, MB*LB^2/12, MB*LB^2/12
INERTIA C, 0, MC*LC^2/12, MC*LC^2/12
GRAVITY(-G*N2>)
% The loop closes where the coupler meets the rocker's tip.
LOOP> = P_O_BC> - (P_O_D> + LC*C1>)
CONFIG[1] = DOT(LOOP>, N1>)
CONFIG[2] = DOT(LOOP>, N2>)
DEPENDENT[1] = DT(CONFIG[1])
DEPENDENT[2] = DT(CONFIG[2])
CONSTRAIN(DEPENDENT[U2, U3])
ZERO = FR() + FRSTAR()
KANE()
INPUT LA = 1, LB = 2.5, LC = 2, LD = 2.5, MA = 1, MB = 2, MC = 1.5, G = 9.81
INPUT Q1 = 1.2, Q2 = 0.3, Q3 = 1.7, U1 = 2
ENERGY = KE() + G*(MA*DOT(P_O_AO>, N2>) + MB*DOT(P_O_BO>, N2>) + MC*DOT(P_O_CO>, N2>))
OUTPUT Q1, Q2, Q3, U2, U3, ENERGY
INPUT TFINAL = 5, ABSERR = 1e-10, RELERR = 1e-10
