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
module gen_forces
    use kinds, only: dp
    implicit none
    private

    public :: generalized_inertia, generalized_forces, inertia_dyadic, cross

contains

    !> Inertia dyadic of R* for R* resolved in n_i: I_n = b^T diag(I) b (b = rows b_i, eq. (10)).
    pure function inertia_dyadic(bmat, inertia) result(in)
        real(dp), intent(in) :: bmat(3, 3)     !! b_ij of eq. (11)
        real(dp), intent(in) :: inertia(3)     !! principal moments I_1..I_3 over m b'^2
        real(dp) :: in(3, 3)
        integer :: j, k
        do k = 1, 3
            do j = 1, 3
                in(j, k) = sum(inertia*bmat(:, j)*bmat(:, k))
            end do
        end do
    end function inertia_dyadic

    !> Generalized inertia M = Jv^T Jv + Jw^T I_n Jw (mass 1): the coefficients of qddot in
    !! -(F*_r) of eqs. (33), (36).  Five generalized coordinates.
    pure function generalized_inertia(jv, jw, in) result(m)
        real(dp), intent(in) :: jv(3, 5)       !! partial velocities of R*
        real(dp), intent(in) :: jw(3, 5)       !! partial angular velocities
        real(dp), intent(in) :: in(3, 3)       !! inertia dyadic in n_i
        real(dp) :: m(5, 5)
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
    end function generalized_inertia

    !> f_r = F_r + (F*_r at qddot = 0): gravity, eq. (32), and the velocity terms of
    !! eqs. (33)-(36) with the inertia torque T of eq. (35) resolved in n_i.
    pure function generalized_forces(jv, cv, jw, cw, omega, in) result(f)
        real(dp), intent(in) :: jv(3, 5)       !! partial velocities of R*
        real(dp), intent(in) :: cv(3)          !! acceleration of R* at qddot = 0
        real(dp), intent(in) :: jw(3, 5)       !! partial angular velocities
        real(dp), intent(in) :: cw(3)          !! angular acceleration at qddot = 0
        real(dp), intent(in) :: omega(3)       !! angular velocity
        real(dp), intent(in) :: in(3, 3)       !! inertia dyadic in n_i
        real(dp) :: f(5)
        real(dp) :: t0(3), iw(3), a(3)
        integer :: r
        iw = in(:, 1)*omega(1) + in(:, 2)*omega(2) + in(:, 3)*omega(3)
        t0 = -(in(:, 1)*cw(1) + in(:, 2)*cw(2) + in(:, 3)*cw(3)) - cross(omega, iw)
        a = cv
        a(3) = a(3) + 1.0_dp            ! a + g n3 (g = 1)
        do r = 1, 5
            f(r) = -(jv(1, r)*a(1) + jv(2, r)*a(2) + jv(3, r)*a(3)) &
                   + jw(1, r)*t0(1) + jw(2, r)*t0(2) + jw(3, r)*t0(3)
        end do
    end function generalized_forces

    !> Vector product a x b.
    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
    end function cross

end module gen_forces
