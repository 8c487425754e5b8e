!> Kinematics of the bifilar pendulum, Kane & Tseng (1966) eqs. (12)-(31).
!!
!! Everything is in lengths over b' (b' = 1).  The misprints of eqs. (24) (v24) and (27)
!! (vdot11, vdot12) are corrected as listed in ../shared/paper/NOTES.md; every coefficient
!! is checked against finite differences of positions in the tests.
module kinematics
    use kinds, only: dp
    use geometry, only: pendulum_t
    implicit none
    private

    public :: omega_coeffs, omega_dot_quadratic, v_coeffs, vdot_coeffs

contains

    !> Coefficients of thdot_j in Omega_i, eq. (14): omega = sum_i Omega_i n_i,
    !! Omega_i = sum_j w(i,j) thdot_j (columns 2 and 3 are zero).
    pure function omega_coeffs(th) result(w)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp) :: w(3, 5)
        real(dp) :: s4, c4, s5, c5
        s4 = sin(th(4)); c4 = cos(th(4)); s5 = sin(th(5)); c5 = cos(th(5))
        w = 0.0_dp
        w(:, 1) = [-s4*c5, -c4*c5, -s5]
        w(:, 4) = [0.0_dp, 0.0_dp, -1.0_dp]
        w(:, 5) = [c4, -s4, 0.0_dp]
    end function omega_coeffs

    !> The velocity-dependent part of A_i, eq. (19): A_i = sum_j w(i,j) thddot_j + this.
    pure function omega_dot_quadratic(th, thd) result(aq)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp), intent(in) :: thd(5)      !! their rates (rad per unit tau)
        real(dp) :: aq(3)
        real(dp) :: s4, c4, s5, c5
        s4 = sin(th(4)); c4 = cos(th(4)); s5 = sin(th(5)); c5 = cos(th(5))
        aq(1) = -c4*c5*thd(1)*thd(4) + s4*s5*thd(1)*thd(5) - s4*thd(4)*thd(5)
        aq(2) = s4*c5*thd(1)*thd(4) + c4*s5*thd(1)*thd(5) - c4*thd(4)*thd(5)
        aq(3) = -c5*thd(1)*thd(5)
    end function omega_dot_quadratic

    !> v_ij of eq. (24): velocity of R* is sum_i sum_j v(i,j) thdot_j n_i.
    pure function v_coeffs(p, th) result(v)
        type(pendulum_t), intent(in) :: p   !! scaled parameters (L, r, lambda)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp) :: v(3, 5)
        real(dp) :: s1, c1, s2, c2, s3, c3, s4, c4, s5, c5, sl, cl, r, l
        s1 = sin(th(1)); c1 = cos(th(1)); s2 = sin(th(2)); c2 = cos(th(2))
        s3 = sin(th(3)); c3 = cos(th(3)); s4 = sin(th(4)); c4 = cos(th(4))
        s5 = sin(th(5)); c5 = cos(th(5)); sl = sin(p%lambda); cl = cos(p%lambda)
        r = p%r
        l = p%big_l
        v(1, 1) = r*sl*(c1*c4 - s1*s4*s5)
        v(1, 2) = l*c2*c3
        v(1, 3) = -l*s2*s3
        v(1, 4) = r*(sl*(-s1*s4 + c1*c4*s5) + cl*c4*c5)
        v(1, 5) = r*(-cl*s4*s5 + sl*c1*s4*c5)
        v(2, 1) = -r*sl*(c1*s4 + s1*c4*s5)
        v(2, 2) = l*c2*s3
        v(2, 3) = l*s2*c3
        v(2, 4) = -r*(cl*s4*c5 + sl*(s1*c4 + c1*s4*s5))
        v(2, 5) = r*(sl*c1*c4*c5 - cl*c4*s5)
        v(3, 1) = r*sl*s1*c5
        v(3, 2) = l*s2
        v(3, 3) = 0.0_dp
        v(3, 4) = 0.0_dp
        v(3, 5) = r*(cl*c5 + sl*c1*s5)
    end function v_coeffs

    !> vdot_ij of eq. (27): the acceleration of R* is a_i = sum_j (vdot_ij thdot_j + v_ij thddot_j).
    pure function vdot_coeffs(p, th, thd) result(vd)
        type(pendulum_t), intent(in) :: p   !! scaled parameters (L, r, lambda)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp), intent(in) :: thd(5)      !! their rates (rad per unit tau)
        real(dp) :: vd(3, 5)
        real(dp) :: s1, c1, s2, c2, s3, c3, s4, c4, s5, c5, sl, cl, r, l
        real(dp) :: d1, d2, d3, d4, d5
        s1 = sin(th(1)); c1 = cos(th(1)); s2 = sin(th(2)); c2 = cos(th(2))
        s3 = sin(th(3)); c3 = cos(th(3)); s4 = sin(th(4)); c4 = cos(th(4))
        s5 = sin(th(5)); c5 = cos(th(5)); sl = sin(p%lambda); cl = cos(p%lambda)
        r = p%r
        l = p%big_l
        d1 = thd(1); d2 = thd(2); d3 = thd(3); d4 = thd(4); d5 = thd(5)
        vd(1, 1) = -r*sl*((s1*c4 + c1*s4*s5)*d1 + (c1*s4 + s1*c4*s5)*d4 + s1*s4*c5*d5)
        vd(1, 2) = -l*(s2*c3*d2 + c2*s3*d3)
        vd(1, 3) = -l*(c2*s3*d2 + s2*c3*d3)
        vd(1, 4) = r*(-sl*(c1*s4 + s1*c4*s5)*d1 &
                      - (sl*s1*c4 + sl*c1*s4*s5 + cl*s4*c5)*d4 &
                      + (sl*c1*c4*c5 - cl*c4*s5)*d5)
        vd(1, 5) = r*(-sl*s1*s4*c5*d1 + (sl*c1*c5 - cl*s5)*c4*d4 &
                      - (cl*s4*c5 + sl*c1*s4*s5)*d5)
        vd(2, 1) = -r*sl*((c1*c4*s5 - s1*s4)*d1 + (c1*c4 - s1*s4*s5)*d4 + s1*c4*c5*d5)
        vd(2, 2) = l*(-s2*s3*d2 + c2*c3*d3)
        vd(2, 3) = l*(c2*c3*d2 - s2*s3*d3)
        vd(2, 4) = -r*(sl*(c1*c4 - s1*s4*s5)*d1 &
                       + (cl*c4*c5 - sl*s1*s4 + sl*c1*c4*s5)*d4 &
                       + (sl*c1*s4*c5 - cl*s4*s5)*d5)
        vd(2, 5) = r*(-sl*s1*c4*c5*d1 + (cl*s5 - sl*c1*c5)*s4*d4 &
                      - (sl*c1*c4*s5 + cl*c4*c5)*d5)
        vd(3, 1) = r*sl*(c1*c5*d1 - s1*s5*d5)
        vd(3, 2) = l*c2*d2
        vd(3, 3) = 0.0_dp
        vd(3, 4) = 0.0_dp
        vd(3, 5) = r*(-sl*s1*s5*d1 + (sl*c1*c5 - cl*s5)*d5)
    end function vdot_coeffs

end module kinematics
