"""What each library program computes, as LIST shows an untouched library area in the session.

The programs are Python (yaseer.linkages), so there are no BASIC lines to list; a student
gets instead the program's inputs, its equations written out, and its outputs, by the
array elements a listing uses (docs/contract.md has every element, unit and sign).
Notation: u(x) = (cos x, sin x), the unit vector at angle x; i·v turns v by +90°;
' and '' are the first and second time derivatives.
"""

from __future__ import annotations

LIBRARY_TEXT = {
    1: """\
PROG 1: the slider-crank AoAB (library program, Python)
 in:  crank a = L(2) at angle T(2), turning W(2), A(2) (rad/s, rad/s^2)
      rod b = L(3); cylinder axis at angle T(4), e = L(1) to its right
      D(0), E(0) = a', a'' of a crank that changes length
 A  = a*u(T(2))
 A' = D(0)*u(T(2)) + a*W(2)*i*u(T(2))
 A''= (E(0) - a*W(2)^2)*u(T(2)) + (a*A(2) + 2*D(0)*W(2))*i*u(T(2))
 s  = A.u(T(4)) + SQR(b^2 - (L(1) + A.u(T(4)+90))^2)
 B  = L(1)*u(T(4)-90) + s*u(T(4))          the piston pin
 T(3) = angle of A->B
 s'*u(T(4))  - W(3)*i*(B-A) = A'           gives s' and W(3)
 s''*u(T(4)) - A(3)*i*(B-A) = A'' - W(3)^2*(B-A)   gives s'' and A(3)
 out: T(3), W(3), A(3) the rod
      X(1),Y(1) V(1),V(2) A(33),A(34) crank point R(1),H(1)
      X(2),Y(2) V(3),V(4) A(35),A(36) rod point R(4),H(4) from B
      A(10),A(11) acceleration of the crank's mass centre R(2),H(2)
 Z(1)=2 also solves the forces (F = m*a, M = I*alpha on crank, rod, piston):
      F(3),F(4) at Ao; F(5),F(6) at A; F(10),F(11) at B; N(1) wall;
      and the load Q(1) picks: 1 U(1), 2 F(2), 3 F(9), 4 P(1)
""",
    2: """\
PROG 2: the four-bar AoABBo (library program, Python)
 in:  ground Ao->Bo = L(11)*u(T(11)); crank a = L(12) at angle T(12),
      turning W(5), A(5); coupler b = L(13); follower c = L(14)
      L(10): 1 crossed, -1 follow the motion, else uncrossed
 A  = a*u(T(12));  d = |Bo-A|;  D(2), E(2) = a', a''
 A' = D(2)*u(T(12)) + a*W(5)*i*u(T(12))
 A''= (E(2) - a*W(5)^2)*u(T(12)) + (a*A(5) + 2*D(2)*W(5))*i*u(T(12))
 x  = (b^2 - c^2 + d^2) / (2*d);  h = SQR(b^2 - x^2)
 B  = A + x*u(A->Bo) + h*i*u(A->Bo)       h < 0 when crossed
 T(13) = angle of A->B;  T(14) = angle of B->Bo
 loop A + b*u(T(13)) + c*u(T(14)) = Bo, differentiated:
 W(6)*i*(B-A) + W(7)*i*(Bo-B) = -A'        gives W(6), W(7)
 A(6)*i*(B-A) + A(7)*i*(Bo-B) = -A'' + W(6)^2*(B-A) + W(7)^2*(Bo-B)
 out: T(13), W(6), A(6) coupler;  T(14), W(7), A(7) follower
      X(3),Y(3) V(5),V(6) A(37),A(38) crank point R(9),H(9)
      X(4),Y(4) V(7),V(8) A(39),A(40) coupler point R(11),H(11)
      X(5),Y(5) V(9),V(10) A(41),A(42) follower point R(13),H(13)
 Z(2)=2 also solves the forces on crank, coupler, follower:
      F(21),F(22) at Ao; F(23),F(24) at A; F(25),F(26) at B;
      F(27),F(28) at Bo; the load Q(2) picks: 1 U(2), 2 F(31), 3 F(34), 4 F(37)
""",
    3: """\
PROG 3: the inverted slider-crank (library program, Python)
 in:  ground Bo->Ao = L(6)*u(T(6)); crank a = L(7) at angle T(7),
      turning W(0), A(0); D(3), E(3) = a', a''
 A  = a*u(T(7));  Bo = -L(6)*u(T(6))
 A' = D(3)*u(T(7)) + a*W(0)*i*u(T(7))
 A''= (E(3) - a*W(0)^2)*u(T(7)) + (a*A(0) + 2*D(3)*W(0))*i*u(T(7))
 L(5)*u(T(9)) = A - Bo                     length and angle of Bo->A
 D(4)*u(T(9)) + L(5)*W(4)*i*u(T(9)) = A'   gives D(4), W(4)
 E(4)*u(T(9)) + L(5)*A(4)*i*u(T(9))
      = A'' - 2*D(4)*W(4)*i*u(T(9)) + L(5)*W(4)^2*u(T(9))   gives E(4), A(4)
 out: L(5), D(4), E(4) the slide;  T(9), W(4), A(4) the follower
      X(6),Y(6) V(11),V(12) A(43),A(44) crank point R(0),H(23)
      X(7),Y(7) V(13),V(14) A(45),A(46) follower point R(7),H(6)
 Z(3)=2 also solves the forces on crank, block, follower:
      F(12),F(13) at Ao; F(14),F(15) at A; N(3), U(4) block on follower;
      F(16),F(17) at Bo; the load Q(3) picks: 1 U(3), 3 F(18)
""",
    5: """\
PROG 5: the virtual link, origin to a moving point (library program, Python)
 in:  the point X(10),Y(10); its velocity V(17),V(18);
      its acceleration A(49),A(50)
 L  = SQR(X(10)^2 + Y(10)^2);  T = angle of (X(10), Y(10))
 e  = u(T) along the link,  n = i*e across it
 D(6) = v.e                 L'
 D(5) = v.n / L             T' (rad/s)
 E(6) = a.e + L*D(5)^2      L''
 E(5) = (a.n - 2*D(6)*D(5)) / L            T''
 out: T, L (and X = X(10), Y = Y(10)); D(5), E(5); D(6), E(6)
 (the paper's equations (1)-(4) divide by COS T and SIN T instead:
  --method 5=paper; the printed subroutine: --prog 5=programs/prog5.bas)
""",
}
