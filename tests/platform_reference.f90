!> An independent model of a rigid body hung by n inextensible cables, for the tests of the
!! multifilar platform (suite platform): written from the geometry alone, in maximal
!! coordinates, with the cables as holonomic constraints and Lagrange multipliers.  It
!! shares no code with src/model/platform_*.
!!
!! State (13): the mass centre r and its velocity v (N components), the orientation as a
!! unit quaternion (w, x, y, z) (B to N), the angular velocity in B components.  With
!! b_i = p_i - c the body points from the mass centre (B) and their N images
!! r_i = R b_i, the constraints are g_i = (|r + r_i - S_i|^2 - l_i^2)/2 = 0.  Newton and
!! Euler with the constraint forces lambda_i d_i (d_i = r + r_i - S_i):
!!   m a = -m g n3 + sum lambda_i d_i,
!!   J alpha + omega x J omega = sum lambda_i r_i x d_i        (N components),
!! and the constraints differentiated twice with Baumgarte's terms,
!!   d_i . (a + alpha x r_i) + |v + omega x r_i|^2 + d_i . (omega x (omega x r_i))
!!       + 2 beta g_i' + beta^2 g_i = 0,
!! give n linear equations for lambda.  The quaternion's norm is held by a stabilising term.
!! The tension of cable i is -lambda_i |d_i|.
module platform_reference
    use kinds, only: dp
    use status, only: status_t
    use ode_system, only: ode_system_t
    use lapack_wrap, only: la_solve
    use unused_arg, only: unused
    implicit none
    private

    integer, parameter, public :: REF_NSTATE = 13

    !> The body and its cables.
    type, extends(ode_system_t), public :: ref_body_t
        integer :: n = 3
        real(dp), allocatable :: s(:, :)        !! (3, n) support points, N
        real(dp), allocatable :: b(:, :)        !! (3, n) body points from the mass centre, B
        real(dp), allocatable :: l(:)           !! (n) lengths
        real(dp) :: m = 1.0_dp, g = 1.0_dp
        real(dp) :: j(3, 3) = 0.0_dp            !! inertia about the mass centre, B
        real(dp) :: beta = 10.0_dp              !! Baumgarte's rate
    contains
        procedure :: rhs => ref_rhs
    end type ref_body_t

    public :: ref_rotation, ref_constraints, ref_energy, ref_tensions, ref_quat_of_yaw_tilt

contains

    !> R of a unit quaternion (w, x, y, z).
    pure function ref_rotation(q) result(r)
        real(dp), intent(in) :: q(4)
        real(dp) :: r(3, 3), w, x, y, z, s
        s = 1.0_dp/sqrt(sum(q**2))
        w = q(1)*s; x = q(2)*s; y = q(3)*s; z = q(4)*s
        r(1, :) = [1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)]
        r(2, :) = [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)]
        r(3, :) = [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)]
    end function ref_rotation

    !> The quaternion of a turn by yaw about n3 after small turns tx about n1 and ty about n2
    !! (a body tilted, then turned).
    pure function ref_quat_of_yaw_tilt(yaw, tx, ty) result(q)
        real(dp), intent(in) :: yaw, tx, ty
        real(dp) :: q(4), qz(4), qx(4), qy(4)
        qz = [cos(0.5_dp*yaw), 0.0_dp, 0.0_dp, sin(0.5_dp*yaw)]
        qx = [cos(0.5_dp*tx), sin(0.5_dp*tx), 0.0_dp, 0.0_dp]
        qy = [cos(0.5_dp*ty), 0.0_dp, sin(0.5_dp*ty), 0.0_dp]
        q = qmul(qz, qmul(qy, qx))
    end function ref_quat_of_yaw_tilt

    pure function qmul(a, b) result(c)
        real(dp), intent(in) :: a(4), b(4)
        real(dp) :: c(4)
        c(1) = a(1)*b(1) - a(2)*b(2) - a(3)*b(3) - a(4)*b(4)
        c(2) = a(1)*b(2) + a(2)*b(1) + a(3)*b(4) - a(4)*b(3)
        c(3) = a(1)*b(3) - a(2)*b(4) + a(3)*b(1) + a(4)*b(2)
        c(4) = a(1)*b(4) + a(2)*b(3) - a(3)*b(2) + a(4)*b(1)
    end function qmul

    pure function crs(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
    end function crs

    !> The constraints g_i and their rates at state y.
    pure subroutine ref_constraints(sys, y, g, gd)
        type(ref_body_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: g(:), gd(:)
        real(dp) :: r(3, 3), ri(3), d(3), w(3)
        integer :: i
        r = ref_rotation(y(7:10))
        w = matmul(r, y(11:13))
        do i = 1, sys%n
            ri = matmul(r, sys%b(:, i))
            d = y(1:3) + ri - sys%s(:, i)
            g(i) = 0.5_dp*(dot_product(d, d) - sys%l(i)**2)
            gd(i) = dot_product(d, y(4:6) + crs(w, ri))
        end do
    end subroutine ref_constraints

    !> Kinetic + potential energy.
    pure real(dp) function ref_energy(sys, y) result(e)
        type(ref_body_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        e = 0.5_dp*sys%m*dot_product(y(4:6), y(4:6)) + &
            0.5_dp*dot_product(y(11:13), matmul(sys%j, y(11:13))) + sys%m*sys%g*y(3)
    end function ref_energy

    !> Accelerations and multipliers at state y.
    subroutine accelerations(sys, y, a, alpha_b, lam, stat)
        type(ref_body_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: a(3), alpha_b(3), lam(:)
        type(status_t), intent(out) :: stat
        real(dp) :: r(3, 3), jn(3, 3), jinv(3, 3), w(3), ri(3, sys%n), d(3, sys%n), &
                    mat(sys%n, sys%n), rhs(sys%n), g(sys%n), gd(sys%n), a0(3), al0(3), &
                    ai(3), ali(3), vi(3), alpha(3), h(3)
        integer :: i, k
        r = ref_rotation(y(7:10))
        jn = matmul(r, matmul(sys%j, transpose(r)))
        call inverse3(jn, jinv)
        w = matmul(r, y(11:13))
        call ref_constraints(sys, y, g, gd)
        do i = 1, sys%n
            ri(:, i) = matmul(r, sys%b(:, i))
            d(:, i) = y(1:3) + ri(:, i) - sys%s(:, i)
        end do
        ! free accelerations (lambda = 0)
        a0 = [0.0_dp, 0.0_dp, -sys%g]
        h = crs(w, matmul(jn, w))
        al0 = -matmul(jinv, h)
        do i = 1, sys%n
            vi = y(4:6) + crs(w, ri(:, i))
            rhs(i) = -dot_product(d(:, i), a0 + crs(al0, ri(:, i))) - dot_product(vi, vi) &
                     - dot_product(d(:, i), crs(w, crs(w, ri(:, i)))) &
                     - 2.0_dp*sys%beta*gd(i) - sys%beta**2*g(i)
            do k = 1, sys%n
                ! the accelerations lambda_k = 1 adds
                ai = d(:, k)/sys%m
                ali = matmul(jinv, crs(ri(:, k), d(:, k)))
                mat(i, k) = dot_product(d(:, i), ai + crs(ali, ri(:, i)))
            end do
        end do
        lam = rhs
        call la_solve(mat, lam, stat)
        if (stat%code /= 0) return
        a = a0
        alpha = al0
        do k = 1, sys%n
            a = a + lam(k)*d(:, k)/sys%m
            alpha = alpha + lam(k)*matmul(jinv, crs(ri(:, k), d(:, k)))
        end do
        alpha_b = matmul(transpose(r), alpha)
    end subroutine accelerations

    !> The cable tensions at state y.
    subroutine ref_tensions(sys, y, tn, stat)
        type(ref_body_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: tn(:)
        type(status_t), intent(out) :: stat
        real(dp) :: a(3), al(3), lam(sys%n), r(3, 3), d(3)
        integer :: i
        call accelerations(sys, y, a, al, lam, stat)
        r = ref_rotation(y(7:10))
        do i = 1, sys%n
            d = y(1:3) + matmul(r, sys%b(:, i)) - sys%s(:, i)
            tn(i) = -lam(i)*norm2(d)
        end do
    end subroutine ref_tensions

    subroutine ref_rhs(sys, t, y, ydot, stat)
        class(ref_body_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        real(dp) :: a(3), alpha_b(3), lam(sys%n), q(4), wb(3), nq
        call unused(t)
        ydot = 0.0_dp
        call accelerations(sys, y, a, alpha_b, lam, stat)
        if (stat%code /= 0) return
        q = y(7:10)
        wb = y(11:13)
        nq = sum(q**2)
        ydot(1:3) = y(4:6)
        ydot(4:6) = a
        ydot(7:10) = 0.5_dp*qmul(q, [0.0_dp, wb]) + (1.0_dp - nq)*q
        ! alpha in B components: omega_b' = R^T alpha (the frame's own turning adds nothing
        ! to a vector's rate resolved in it when that vector is omega itself)
        ydot(11:13) = alpha_b
    end subroutine ref_rhs

    pure subroutine inverse3(a, ai)
        real(dp), intent(in) :: a(3, 3)
        real(dp), intent(out) :: ai(3, 3)
        real(dp) :: det
        ai(1, 1) = a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)
        ai(1, 2) = a(1, 3)*a(3, 2) - a(1, 2)*a(3, 3)
        ai(1, 3) = a(1, 2)*a(2, 3) - a(1, 3)*a(2, 2)
        ai(2, 1) = a(2, 3)*a(3, 1) - a(2, 1)*a(3, 3)
        ai(2, 2) = a(1, 1)*a(3, 3) - a(1, 3)*a(3, 1)
        ai(2, 3) = a(1, 3)*a(2, 1) - a(1, 1)*a(2, 3)
        ai(3, 1) = a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1)
        ai(3, 2) = a(1, 2)*a(3, 1) - a(1, 1)*a(3, 2)
        ai(3, 3) = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
        det = a(1, 1)*ai(1, 1) + a(1, 2)*ai(2, 1) + a(1, 3)*ai(3, 1)
        ai = ai/det
    end subroutine inverse3

end module platform_reference
