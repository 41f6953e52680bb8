10 FOR QQ = 360.1 TO .1 STEP - 20: GOSUB 100: GOSUB PROG 1
20 X(10) = X(2): Y(10) = Y(2): V(17) = V(3): V(18) = V(4): A(49) = A(35): A(50) = A(36): GOSUB PROG 5
30 L(2) = L: D(0) = D(6): E(0) = E(6): T(2) = T: W(2) = D(5): A(2) = E(5)
40 T(4) = 90.1: L(1) = .08: L(3) = .054: R(4) = 0: GOSUB PROG 1
50 IF V(4) > 0 THEN P(1) = 650 * V(4) ^ 2 ELSE P(1) = -650 * V(4) ^ 2
60 Z(1) = 2: Q(1) = 1: GOSUB PROG 1
70 P(1) = 0: F(7) = -F(5): F(8) = -F(6): GOSUB 100: GOSUB PROG 1
80 LPRINT USING "#####.#"; QQ; U(1); N(1); SQR(F(3) ^ 2 + F(4) ^ 2): NEXT QQ: END
100 T(2) = QQ: L(1) = 0: T(4) = .1: L(2) = .021: D(0) = 0: E(0) = 0: W(2) = -8: A(2) = 0: L(3) = .032: R(4) = .029: H(4) = 180: RETURN
