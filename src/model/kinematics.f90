!> Kinematics of the bifilar pendulum, Kane & Tseng (1966) eqs. (12)-(31).
!!
!! Everything is in lengths over b' (b' = 1) and reads the pose's trigonometry from a
!! pose_t (module geometry) under the paper's names s1, c1, ..., s_lambda, c_lambda.
!!
!! Two forms of the same kinematics:
!! * the paper's component forms: Omega_ij of eq. (14) (omega_partials), the velocity terms
!!   of A_i, eq. (19) (omega_conv), v_ij of eq. (24) (v_partials) and vdot_ij of eq. (27)
!!   (vdot_partials), with the misprints of eqs. (24) (v24) and (27) (vdot11, vdot12)
!!   corrected as listed in ../shared/paper/NOTES.md.  The paper's form of eq. (38) uses
!!   them; the tests check every coefficient against finite differences of positions.
!! * the rigid-body form of eqs. (24), (27) for a point P fixed in the body at u = P - C:
!!   its partial velocities for theta_1, theta_4, theta_5 are Omega_j x u (the body columns of
!!   v_ij for u = R* - C), and the part of its acceleration that does not depend on the
!!   second derivatives is A_conv x u + omega x (omega x u) (sum_j vdot_ij thdot_j for the
!!   body columns).  The integrated model (bifilar_model) uses this form, which takes a
!!   quarter of the arithmetic, and its derivatives (the *_tangent routines) give the
!!   Jacobian Z of eq. (51) exactly.
!!
!! The functions of theta (omega_coeffs, omega_dot_quadratic, v_coeffs, vdot_coeffs) fill a
!! pose and call the pose forms; they serve the tests and the elastic model.
module kinematics
    use kinds, only: dp
    use vectors, only: cross
    use geometry, only: pendulum_t, pose_t, pose_of, body_pose
    implicit none
    private

    public :: omega_coeffs, omega_dot_quadratic, v_coeffs, vdot_coeffs
    public :: omega_partials, omega_conv, v_partials, vdot_partials
    public :: omega_partials_tangent, omega_conv_tangent

contains

    !> Omega_ij of eq. (14) from a pose: omega = sum_i Omega_i n_i, Omega_i = sum_j w(i,j)
    !! thdot_j.  Columns 2 and 3 are zero; column 1 is ntilde_3 (theta_1 turns the body about
    !! CD), column 4 is -n_3, column 5 is (c4, -s4, 0).
    pure subroutine omega_partials(ps, w)
        type(pose_t), intent(in) :: ps      !! the pose (theta_4, theta_5)
        real(dp), intent(out) :: w(3, 5)    !! partial angular velocities, resolved in n_i
        w(:, 1) = [-ps%s4*ps%c5, -ps%c4*ps%c5, -ps%s5]
        w(:, 2:3) = 0.0_dp
        w(:, 4) = [0.0_dp, 0.0_dp, -1.0_dp]
        w(:, 5) = [ps%c4, -ps%s4, 0.0_dp]
    end subroutine omega_partials

    !> The velocity terms of A_i, eq. (19): the angular acceleration is
    !! sum_j Omega_ij thddot_j + aq(i).
    pure subroutine omega_conv(ps, thd, aq)
        type(pose_t), intent(in) :: ps      !! the pose (theta_4, theta_5)
        real(dp), intent(in) :: thd(5)      !! rates (rad per unit tau)
        real(dp), intent(out) :: aq(3)
        associate (s4 => ps%s4, c4 => ps%c4, s5 => ps%s5, c5 => ps%c5)
            aq(1) = -c4*c5*thd(1)*thd(4) + s4*s5*thd(1)*thd(5) - s4*thd(4)*thd(5)
            aq(2) = s4*c5*thd(1)*thd(4) + c4*s5*thd(1)*thd(5) - c4*thd(4)*thd(5)
            aq(3) = -c5*thd(1)*thd(5)
        end associate
    end subroutine omega_conv

    !> Derivative of omega_partials along a change dth of the angles (columns 1 and 5 change).
    pure subroutine omega_partials_tangent(ps, dth, dw)
        type(pose_t), intent(in) :: ps      !! the pose
        real(dp), intent(in) :: dth(5)      !! change of theta_1..theta_5
        real(dp), intent(out) :: dw(3, 5)   !! change of Omega_ij
        dw = 0.0_dp
        dw(:, 1) = [-ps%c4*ps%c5*dth(4) + ps%s4*ps%s5*dth(5), &
                    ps%s4*ps%c5*dth(4) + ps%c4*ps%s5*dth(5), -ps%c5*dth(5)]
        dw(:, 5) = [-ps%s4*dth(4), -ps%c4*dth(4), 0.0_dp]
    end subroutine omega_partials_tangent

    !> Derivative of omega_conv along a change (dth, dthd) of angles and rates.
    pure subroutine omega_conv_tangent(ps, thd, dth, dthd, daq)
        type(pose_t), intent(in) :: ps      !! the pose
        real(dp), intent(in) :: thd(5)      !! rates
        real(dp), intent(in) :: dth(5), dthd(5)  !! changes of angles and rates
        real(dp), intent(out) :: daq(3)
        real(dp) :: d14, d15, d45, dd14, dd15, dd45, ds4, dc4, ds5, dc5
        d14 = thd(1)*thd(4)
        d15 = thd(1)*thd(5)
        d45 = thd(4)*thd(5)
        dd14 = dthd(1)*thd(4) + thd(1)*dthd(4)
        dd15 = dthd(1)*thd(5) + thd(1)*dthd(5)
        dd45 = dthd(4)*thd(5) + thd(4)*dthd(5)
        ds4 = ps%c4*dth(4)
        dc4 = -ps%s4*dth(4)
        ds5 = ps%c5*dth(5)
        dc5 = -ps%s5*dth(5)
        daq(1) = -(dc4*ps%c5 + ps%c4*dc5)*d14 - ps%c4*ps%c5*dd14 &
                 + (ds4*ps%s5 + ps%s4*ds5)*d15 + ps%s4*ps%s5*dd15 - ds4*d45 - ps%s4*dd45
        daq(2) = (ds4*ps%c5 + ps%s4*dc5)*d14 + ps%s4*ps%c5*dd14 &
                 + (dc4*ps%s5 + ps%c4*ds5)*d15 + ps%c4*ps%s5*dd15 - dc4*d45 - ps%c4*dd45
        daq(3) = -dc5*d15 - ps%c5*dd15
    end subroutine omega_conv_tangent

    !> v_ij of eq. (24) from a pose: the velocity of R* is sum_i sum_j v(i,j) thdot_j n_i.
    pure subroutine v_partials(p, ps, v)
        type(pendulum_t), intent(in) :: p   !! scaled parameters (L, r)
        type(pose_t), intent(in) :: ps      !! the pose (all five angles and lambda)
        real(dp), intent(out) :: v(3, 5)
        real(dp) :: r, l
        associate (s1 => ps%s1, c1 => ps%c1, s2 => ps%s2, c2 => ps%c2, s3 => ps%s3, &
                   c3 => ps%c3, s4 => ps%s4, c4 => ps%c4, s5 => ps%s5, c5 => ps%c5, &
                   sl => ps%s_lambda, cl => ps%c_lambda)
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
        end associate
    end subroutine v_partials

    !> vdot_ij of eq. (27) from a pose: the acceleration of R* is
    !! a_i = sum_j (vdot_ij thdot_j + v_ij thddot_j).
    pure subroutine vdot_partials(p, ps, thd, vd)
        type(pendulum_t), intent(in) :: p   !! scaled parameters (L, r)
        type(pose_t), intent(in) :: ps      !! the pose (all five angles and lambda)
        real(dp), intent(in) :: thd(5)      !! rates (rad per unit tau)
        real(dp), intent(out) :: vd(3, 5)
        real(dp) :: r, l, d1, d2, d3, d4, d5
        associate (s1 => ps%s1, c1 => ps%c1, s2 => ps%s2, c2 => ps%c2, s3 => ps%s3, &
                   c3 => ps%c3, s4 => ps%s4, c4 => ps%c4, s5 => ps%s5, c5 => ps%c5, &
                   sl => ps%s_lambda, cl => ps%c_lambda)
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
        end associate
    end subroutine vdot_partials

    !> Coefficients of thdot_j in Omega_i, eq. (14), at the angles th.
    pure function omega_coeffs(th) result(w)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp) :: w(3, 5)
        call omega_partials(body_pose(th(1), th(4), th(5), 0.0_dp), w)
    end function omega_coeffs

    !> The velocity-dependent part of A_i, eq. (19), at the angles th and rates thd.
    pure function omega_dot_quadratic(th, thd) result(aq)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp), intent(in) :: thd(5)      !! their rates (rad per unit tau)
        real(dp) :: aq(3)
        call omega_conv(body_pose(th(1), th(4), th(5), 0.0_dp), thd, aq)
    end function omega_dot_quadratic

    !> v_ij of eq. (24) at the angles th.
    pure function v_coeffs(p, th) result(v)
        type(pendulum_t), intent(in) :: p   !! scaled parameters (L, r, lambda)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp) :: v(3, 5)
        call v_partials(p, pose_of(th, p%lambda), v)
    end function v_coeffs

    !> vdot_ij of eq. (27) at the angles th and rates thd.
    pure function vdot_coeffs(p, th, thd) result(vd)
        type(pendulum_t), intent(in) :: p   !! scaled parameters (L, r, lambda)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp), intent(in) :: thd(5)      !! their rates (rad per unit tau)
        real(dp) :: vd(3, 5)
        call vdot_partials(p, pose_of(th, p%lambda), thd, vd)
    end function vdot_coeffs

end module kinematics
