!> Generalized forces of the bifilar pendulum, Kane & Tseng (1966) eqs. (32)-(37).
!!
!! For generalized coordinates q_1..q_5 with the velocity of R* equal to Jv qdot and the
!! angular velocity equal to Jw qdot (both resolved in n_1, n_2, n_3), and accelerations
!! a = Jv qddot + cv, alpha = Jw qddot + cw, the generalized active and inertia forces for
!! the partial rates of change Jv(:,r), Jw(:,r) (r = 1..5) are
!!     F_r  = Jv(:,r) . (-m g n3)                                 eq. (32)
!!     F*_r = Jv(:,r) . (-m a) + Jw(:,r) . T,   T = -I alpha - omega x (I omega)   eqs. (33)-(35)
!! so that F_r + F*_r = f_r - sum_j M_rj qddot_j with the generalized inertia M and the
!! velocity and gravity terms f computed here.  Kane's equations (37) for the independent
!! speeds are these rows combined with the constraint (see bifilar_model).  Units: m = g = 1.
!!
!! Forces enter as a resultant force on R* and a resultant torque on the body, projected on
!! the partial velocities (project): F_r + F*_r = Jv(:,r) . force + Jw(:,r) . torque.  An
!! active torque M on the body (e.g. damping about the vertical, M = -(c_v W + c_q |W| W) n3
!! with W = omega . n3) is added to `torque` before the projection; a force on R* to
!! `force`.  (A velocity-dependent one also enters the derivative of the right-hand side
!! in bifilar_model's eom_tangent, through omega's change.)
module gen_forces
    use kinds, only: dp
    use kinematics, only: cross
    implicit none
    private

    public :: generalized_inertia, inertia_torque, project, inertia_dyadic

contains

    !> Inertia dyadic of R* for R* resolved in n_i: I_n = b^T diag(I) b (b = rows b_i, eq. (10)).
    pure function inertia_dyadic(bmat, inertia) result(in)
        real(dp), intent(in) :: bmat(3, 3)     !! b_ij of eq. (11)
        real(dp), intent(in) :: inertia(3)     !! principal moments I_1..I_3 over m b'^2
        real(dp) :: in(3, 3)
        integer :: j, k
        do k = 1, 3
            do j = 1, 3
                in(j, k) = inertia(1)*bmat(1, j)*bmat(1, k) + inertia(2)*bmat(2, j)*bmat(2, k) &
                           + inertia(3)*bmat(3, j)*bmat(3, k)
            end do
        end do
    end function inertia_dyadic

    !> Generalized inertia M = Jv^T Jv + Jw^T I_n Jw (mass 1): the coefficients of qddot in
    !! -(F*_r) of eqs. (33), (36).  Five generalized coordinates.
    pure subroutine generalized_inertia(jv, jw, in, m)
        real(dp), intent(in) :: jv(3, 5)       !! partial velocities of R*
        real(dp), intent(in) :: jw(3, 5)       !! partial angular velocities
        real(dp), intent(in) :: in(3, 3)       !! inertia dyadic in n_i
        real(dp), intent(out) :: m(5, 5)
        real(dp) :: iw(3, 5)
        integer :: r, j
        do j = 1, 5
            iw(:, j) = in(:, 1)*jw(1, j) + in(:, 2)*jw(2, j) + in(:, 3)*jw(3, j)
        end do
        do j = 1, 5
            do r = j, 5
                m(r, j) = jv(1, r)*jv(1, j) + jv(2, r)*jv(2, j) + jv(3, r)*jv(3, j) &
                          + jw(1, r)*iw(1, j) + jw(2, r)*iw(2, j) + jw(3, r)*iw(3, j)
                m(j, r) = m(r, j)
            end do
        end do
    end subroutine generalized_inertia

    !> The inertia torque of eq. (35), T = -I_n alpha - omega x (I_n omega).
    pure function inertia_torque(in, alpha, omega) result(t)
        real(dp), intent(in) :: in(3, 3)       !! inertia dyadic in n_i
        real(dp), intent(in) :: alpha(3)       !! angular acceleration
        real(dp), intent(in) :: omega(3)       !! angular velocity
        real(dp) :: t(3)
        real(dp) :: iw(3)
        iw = in(:, 1)*omega(1) + in(:, 2)*omega(2) + in(:, 3)*omega(3)
        t = -(in(:, 1)*alpha(1) + in(:, 2)*alpha(2) + in(:, 3)*alpha(3)) - cross(omega, iw)
    end function inertia_torque

    !> Generalized forces of a resultant force on R* and a resultant torque on the body:
    !! f_r = Jv(:,r) . force + Jw(:,r) . torque, eqs. (32)-(36).  With force = -(cv + g n3)
    !! and torque = inertia_torque(I_n, cw, omega) this is f_r = F_r + (F*_r at qddot = 0).
    pure subroutine project(jv, jw, force, torque, f)
        real(dp), intent(in) :: jv(3, 5)       !! partial velocities of R*
        real(dp), intent(in) :: jw(3, 5)       !! partial angular velocities
        real(dp), intent(in) :: force(3)       !! resultant force on R* (over m g)
        real(dp), intent(in) :: torque(3)      !! resultant torque on the body (over m g b')
        real(dp), intent(out) :: f(5)
        integer :: r
        do r = 1, 5
            f(r) = jv(1, r)*force(1) + jv(2, r)*force(2) + jv(3, r)*force(3) &
                   + jw(1, r)*torque(1) + jw(2, r)*torque(2) + jw(3, r)*torque(3)
        end do
    end subroutine project

end module gen_forces
