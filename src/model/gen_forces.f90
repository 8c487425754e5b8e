!> Generalized forces of the bifilar pendulum, Kane & Tseng (1966) eqs. (32)-(37).
!!
!! For generalized coordinates q_1..q_5 with the velocity of R* equal to Jv qdot (resolved in
!! n_1, n_2, n_3) and the angular velocity equal to Wb qdot (resolved in the body's principal
!! axes b_1, b_2, b_3 of eq. (10)), and accelerations a = Jv qddot + cv,
!! alpha = Wb qddot + cwb, the generalized active and inertia forces for the partial rates of
!! change Jv(:,r), Wb(:,r) (r = 1..5) are
!!     F_r  = Jv(:,r) . (-m g n3)                                 eq. (32)
!!     F*_r = Jv(:,r) . (-m a) + Wb(:,r) . T                      eqs. (33), (36)
!! with the inertia torque of eq. (35) in Euler's form along the principal axes,
!!     T_i = -I_i alpha_i - (omega x I omega)_i,
!! so that F_r + F*_r = f_r - sum_j M_rj qddot_j with the generalized inertia M and the
!! velocity and gravity terms f computed here.  Kane's equations (37) for the independent
!! speeds are these rows combined with the constraint (see bifilar_model).  Units: m = g = 1.
!!
!! Forces enter as a resultant force on R* and a resultant torque on the body, projected on
!! the partial velocities (project): F_r + F*_r = Jv(:,r) . force + Wb(:,r) . torque.  An
!! active torque M on the body (e.g. damping about the vertical, M = -(c_v W + c_q |W| W) n3
!! with W = omega . n3) is added to `torque` (in principal axes: M_i = M . b_i) before the
!! projection; a force on R* to `force`.  (A velocity-dependent one also enters the
!! derivative of the right-hand side in bifilar_model's eom_tangent, through omega's change.)
module gen_forces
    use kinds, only: dp
    use vectors, only: cross
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
            do j = k, 3
                in(j, k) = inertia(1)*bmat(1, j)*bmat(1, k) + inertia(2)*bmat(2, j)*bmat(2, k) &
                           + inertia(3)*bmat(3, j)*bmat(3, k)
                in(k, j) = in(j, k)
            end do
        end do
    end function inertia_dyadic

    !> Generalized inertia M = Jv^T Jv + Wb^T diag(I) Wb (mass 1) for n speeds with the
    !! partial velocities Jv, Wb: the coefficients of their derivatives in -(F*_r) of eqs.
    !! (33), (36).  Only the lower triangle (r >= j) is filled.
    pure subroutine generalized_inertia(n, jv, wb, inertia, m)
        integer, intent(in) :: n               !! number of speeds
        real(dp), intent(in) :: jv(3, n)       !! partial velocities of R* (in n_i)
        real(dp), intent(in) :: wb(3, n)       !! partial angular velocities (in b_i)
        real(dp), intent(in) :: inertia(3)     !! principal moments I_1..I_3 over m b'^2
        real(dp), intent(out) :: m(n, n)       !! lower triangle
        real(dp) :: iw(3)
        integer :: r, j
        !GCC$ unroll 8
        do j = 1, n
            iw = inertia*wb(:, j)
            !GCC$ unroll 8
            do r = j, n
                m(r, j) = (jv(1, r)*jv(1, j) + jv(2, r)*jv(2, j) + jv(3, r)*jv(3, j)) &
                          + (wb(1, r)*iw(1) + wb(2, r)*iw(2) + wb(3, r)*iw(3))
            end do
        end do
    end subroutine generalized_inertia

    !> The inertia torque of eq. (35) in Euler's form, along the principal axes:
    !! T = -I alpha - omega x (I omega), I = diag(I_1, I_2, I_3).
    pure function inertia_torque(inertia, alpha, omega) result(t)
        real(dp), intent(in) :: inertia(3)     !! principal moments
        real(dp), intent(in) :: alpha(3)       !! angular acceleration (in b_i)
        real(dp), intent(in) :: omega(3)       !! angular velocity (in b_i)
        real(dp) :: t(3)
        t = -inertia*alpha - cross(omega, inertia*omega)
    end function inertia_torque

    !> Generalized forces of a resultant force on R* and a resultant torque on the body for n
    !! speeds: f_r = Jv(:,r) . force + Wb(:,r) . torque, eqs. (32)-(36).  With force =
    !! -(cv + g n3) and torque = inertia_torque(I, cwb, omega) this is f_r = F_r + (F*_r at
    !! qddot = 0).
    pure subroutine project(n, jv, wb, force, torque, f)
        integer, intent(in) :: n               !! number of speeds
        real(dp), intent(in) :: jv(3, n)       !! partial velocities of R* (in n_i)
        real(dp), intent(in) :: wb(3, n)       !! partial angular velocities (in b_i)
        real(dp), intent(in) :: force(3)       !! resultant force on R* (over m g, in n_i)
        real(dp), intent(in) :: torque(3)      !! resultant torque on the body (over m g b',
                                               !! in b_i)
        real(dp), intent(out) :: f(n)
        integer :: r
        !GCC$ unroll 8
        do r = 1, n
            f(r) = (jv(1, r)*force(1) + jv(2, r)*force(2) + jv(3, r)*force(3)) &
                   + (wb(1, r)*torque(1) + wb(2, r)*torque(2) + wb(3, r)*torque(3))
        end do
    end subroutine project

end module gen_forces
