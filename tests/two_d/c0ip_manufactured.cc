// The C0IP crack operator's manufactured solution of ../c0ip_manufactured.cc
// in two dimensions (the plane-strain build: the unit square, penalty
// (d/2) p (p + 1) = p (p + 1)): the L2, H1 and broken-H2 orders of Q2 and Q3
// on three meshes reach the same minimum orders as in 3-D.
#include "../c0ip_manufactured.cc"
