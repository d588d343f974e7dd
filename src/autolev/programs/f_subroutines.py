"""KUTTA and SOLVE, the subroutines a CODE DYNAMICS() program in Fortran calls (f.py
writes the program), in Autolev 3.2's fixed form; a program written with NOSUBS leaves
them out."""
from __future__ import annotations


def kutta_and_solve(numy: int) -> list[str]:
    """KUTTA and SOLVE as the program calls them, KUTTA's work arrays sized for `numy`
    states (a program written with NOSUBS leaves them out; its user links their own)."""
    return (["C" + "*" * 70] + [line.replace("@NUMY@", str(numy)) for line in _KUTTA]
            + ["", ""] + ["C" + "*" * 70] + _SOLVE)


# Autolev's integrator as its Fortran programs call it (docs/language.md), written for
# autolev: COM 1 uses the derivatives of the last stage again at the start of the next
# internal step, where the C programs evaluate them afresh
_KUTTA = r"""
      SUBROUTINE       KUTTA(EQNS, NUMY, Y, T, INTEGSTP, ABSERR, RELERR,
     &COM, *)
C**   Kutta-Merson with a variable step (L. Fox, 1962): advances T by
C**   INTEGSTP.  COM 0: the derivatives at the start only; 1: a step,
C**   the derivatives of the last stage used at the start of the next
C**   internal step.  A step is halved while, for some Y, the error
C**   estimate is at least both RELERR*|Y| and ABSERR (20 times at most,
C**   then RETURN 1), and doubled when the estimate is 64 times smaller.
      IMPLICIT         DOUBLE PRECISION (A - Z)
      INTEGER          NUMY, COM, NUMCUTS, I, MAXY
      LOGICAL          BAD, TWICE
      EXTERNAL         EQNS
      PARAMETER        (MAXY = @NUMY@)
      DIMENSION        Y(NUMY), F0(MAXY), F1(MAXY), F2(MAXY), Y1(MAXY),
     &Y2(MAXY)
      SAVE             HC, NUMCUTS
      DATA             HC, NUMCUTS / 0.0D0, 20 /

      IF( NUMY .GT. MAXY ) THEN
        WRITE(*,*) 'KUTTA: at most', MAXY, ' states'
        RETURN 1
      ENDIF
      IF( COM .EQ. 0 ) THEN
        CALL EQNS(T, Y, F0, 1)
        RETURN
      ENDIF
      IF( INTEGSTP .EQ. 0 ) THEN
        WRITE(*,*) 'KUTTA: the integration step is 0'
        RETURN 1
      ENDIF
      IF( HC*INTEGSTP .LT. 0 ) HC = -HC
      IF( HC .EQ. 0 ) HC = INTEGSTP
      H      = HC
      TT     = T + H
      TFINAL = T + INTEGSTP
      T      = TFINAL
      CALL EQNS(TT - H, Y, F0, 1)

100   IF( TT + H .EQ. TT ) GOTO 300
      H2 = H*0.5D0
      H3 = H/3.0D0
      H6 = H/6.0D0
      H8 = H*0.125D0
      DO 110 I = 1, NUMY
        Y1(I) = Y(I) + H3*F0(I)
110   CONTINUE
      CALL EQNS(TT - 2.0D0*H3, Y1, F1, 0)
      DO 120 I = 1, NUMY
        Y1(I) = Y(I) + H6*(F0(I) + F1(I))
120   CONTINUE
      CALL EQNS(TT - 2.0D0*H3, Y1, F1, 0)
      DO 130 I = 1, NUMY
        Y1(I) = Y(I) + H8*(F0(I) + 3.0D0*F1(I))
130   CONTINUE
      CALL EQNS(TT - H2, Y1, F2, 0)
      DO 140 I = 1, NUMY
        Y1(I) = Y(I) + H2*(F0(I) - 3.0D0*F1(I) + 4.0D0*F2(I))
140   CONTINUE
      CALL EQNS(TT, Y1, F1, 0)
      BAD   = .FALSE.
      TWICE = .TRUE.
      DO 150 I = 1, NUMY
        Y2(I) = Y(I) + H6*(F0(I) + 4.0D0*F2(I) + F1(I))
        ERROR = ABS(Y1(I) - Y2(I))*0.2D0
        TEST  = ABS(Y1(I))*RELERR
        IF( ERROR .GE. TEST .AND. ERROR .GE. ABSERR ) BAD = .TRUE.
        IF( 64.0D0*ERROR .GT. TEST .AND. 64.0D0*ERROR .GT. ABSERR )
     &    TWICE = .FALSE.
150   CONTINUE
      IF( BAD ) THEN
        H  = H2
        HC = H
        TT = TT - H2
        NUMCUTS = NUMCUTS - 1
        IF( NUMCUTS .GE. 0 ) GOTO 100
        T = TT - H
        WRITE(*,2000) T
        CALL EQNS(T, Y, F0, 0)
        RETURN 1
      ENDIF
      DO 160 I = 1, NUMY
        Y(I) = Y2(I)
160   CONTINUE
      IF( TWICE .AND. ABS(H+H) .LE. ABS(INTEGSTP) .AND.
     &    ABS(TT+H+H) .LE. ABS(TFINAL) ) THEN
        H  = H + H
        HC = H
        NUMCUTS = NUMCUTS + 1
      ENDIF
      IF( TT .EQ. TFINAL ) THEN
        CALL EQNS(TFINAL, Y, F0, 2)
        RETURN
      ENDIF
      TT = TT + H
      IF( (H .GT. 0 .AND. TT .GT. TFINAL - 0.1D0*H) .OR.
     &    (H .LT. 0 .AND. TT .LT. TFINAL - 0.1D0*H) ) THEN
        H  = TFINAL - (TT - H)
        TT = TFINAL
      ENDIF
      DO 170 I = 1, NUMY
        F0(I) = F1(I)
170   CONTINUE
      GOTO 100

300   WRITE(*,2010) H, TT
      RETURN 1
2000  FORMAT(/1X,'THE STEPSIZE HAS BEEN HALVED TOO MANY TIMES; T = ',
     &1PE15.8)
2010  FORMAT(/1X,'THE STEPSIZE OF ',1PE15.7,' IS TOO SMALL RELATIVE',
     &' TO THE TERMINAL TIME OF',/1X,1PE15.7,'.  INTEGRATION HALTED.')
      END""".splitlines()[1:]

_SOLVE = r"""
      SUBROUTINE       SOLVE(N, A, B, X)
C**   A X = B (N by N) by Gaussian elimination with partial pivoting,
C**   each pivot inverted once; it stops when a pivot is exactly zero.
C**   A and B are overwritten.
      IMPLICIT         DOUBLE PRECISION (A - Z)
      INTEGER          N, I, J, K, P
      DIMENSION        A(N,N), B(N), X(N)

      DO 140 K = 1, N
        BIG = ABS(A(K,K))
        P = K
        DO 110 I = K+1, N
          IF( ABS(A(I,K)) .GT. BIG ) THEN
            BIG = ABS(A(I,K))
            P = I
          ENDIF
110     CONTINUE
        IF( BIG .EQ. 0 ) THEN
          WRITE(*,*) 'SOLVE: the coefficient matrix is singular'
          STOP
        ENDIF
        IF( P .NE. K ) THEN
          DO 120 J = 1, N
            S      = A(K,J)
            A(K,J) = A(P,J)
            A(P,J) = S
120       CONTINUE
          S    = B(K)
          B(K) = B(P)
          B(P) = S
        ENDIF
        R    = 1/A(K,K)
        X(K) = R
        DO 130 I = K+1, N
          FACTOR = A(I,K)*R
          IF( FACTOR .NE. 0 ) THEN
            DO 125 J = K+1, N
              A(I,J) = A(I,J) - FACTOR*A(K,J)
125         CONTINUE
            B(I) = B(I) - FACTOR*B(K)
          ENDIF
130     CONTINUE
140   CONTINUE
      DO 160 I = N, 1, -1
        ACC = B(I)
        R   = X(I)
        DO 150 J = I+1, N
          ACC = ACC - A(I,J)*X(J)
150     CONTINUE
        X(I) = ACC*R
160   CONTINUE
      RETURN
      END""".splitlines()[1:]
