% Reactions of a simply supported beam of length L under a load W at A from its left end:
% force and moment balance, solved by CODE ALGEBRAIC.
CONSTANTS L, W, A
VARIABLES RA, RB
EQN[1] = RA + RB - W
EQN[2] = RB*L - W*A
INPUT L = 4 M, W = 1000 N, A = 1 M
CODE ALGEBRAIC(EQN, RA, RB) reactions.c
