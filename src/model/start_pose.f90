!> The start poses of the paper's model: the paper's raised start (theta_1..theta_4 of a body
!! turned about the vertical through O, eq. (49) for b = b') and theta_5 from the constraint
!! eq. (2) by the homotopy of eq. (44).  Both can fail on a geometry that allows no such
!! start; the message says what to change.
module start_pose
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_DECK
    use text, only: sci
    use geometry, only: pendulum_t, constraint_g, beta_coeffs
    implicit none
    private

    public :: raised_angles, solve_theta5

contains

    !> The paper's start recipe: theta_1..theta_4 the body would have with l' = l after being
    !! raised by turning it `amplitude` about the vertical through O (the midpoint of AB),
    !! with CD horizontal and its midpoint on that vertical.  theta_5 is set to 0 here.
    !! For b = b' this gives eq. (49): theta_2 = asin((b'/l) sin(q4/2)), theta_3 = pi - q4/2.
    pure subroutine raised_angles(p, amplitude, th, stat)
        type(pendulum_t), intent(in) :: p   !! scaled parameters
        real(dp), intent(in) :: amplitude   !! rotation about the vertical (rad)
        real(dp), intent(out) :: th(5)      !! theta_1..theta_5 (rad)
        type(status_t), intent(out) :: stat !! ERR_DECK when cable BC cannot reach
        real(dp) :: hx, hy, h2
        character(len=160) :: buf
        th = 0.0_dp
        th(4) = amplitude
        ! C - B, horizontal part: C = O - d/2 with O = (0, -B/2), d = (s4, c4, 0)
        hx = -0.5_dp*sin(amplitude)
        hy = 0.5_dp*p%big_b - 0.5_dp*cos(amplitude)
        h2 = hx**2 + hy**2
        if (h2 >= p%big_l**2) then
            buf = 'l/b'' = '//sci(p%big_l)//': cable BC cannot reach the raised start; '// &
                'needs l/b'' > '//sci(sqrt(h2))
            call set_error(stat, ERR_DECK, '&start amplitude / &suspension l: '//trim(buf))
            return
        end if
        th(2) = asin(sqrt(h2)/p%big_l)
        th(3) = atan2(hy, hx)
        if (h2 == 0.0_dp) th(3) = pi - 0.5_dp*amplitude
    end subroutine raised_angles

    !> Solve eq. (2) for theta_5 given theta_1..theta_4: the homotopy of eq. (44),
    !! G(q5(xi)) = (1 - xi) G(0), dq5/dxi = C/(2 beta_5), integrated from xi = 0 (q5 = 0)
    !! to xi = 1 by classical Runge-Kutta, then polished by Newton on G(q5) = 0.
    pure subroutine solve_theta5(p, th, stat)
        type(pendulum_t), intent(in) :: p   !! scaled parameters
        real(dp), intent(inout) :: th(5)    !! in: theta_1..4; out: theta_5 set
        type(status_t), intent(out) :: stat !! ERR_DECK when no solution is found
        integer, parameter :: nsteps = 32
        real(dp) :: cc, h, k1, k2, k3, k4, g, dg
        integer :: i
        character(len=200) :: buf
        th(5) = 0.0_dp
        cc = constraint_g(p, th)
        h = 1.0_dp/nsteps
        do i = 1, nsteps
            k1 = slope(th(5))
            k2 = slope(th(5) + 0.5_dp*h*k1)
            k3 = slope(th(5) + 0.5_dp*h*k2)
            k4 = slope(th(5) + h*k3)
            th(5) = th(5) + h*(k1 + 2.0_dp*k2 + 2.0_dp*k3 + k4)/6.0_dp
            if (.not. (abs(th(5)) < pi)) exit
        end do
        do i = 1, 20
            g = constraint_g(p, th)
            dg = -2.0_dp*beta5(th(5))
            if (abs(dg) < 1.0e-12_dp .or. .not. (abs(th(5)) < pi)) exit
            th(5) = th(5) - g/dg
            if (abs(g) < 1.0e-15_dp) exit
        end do
        g = constraint_g(p, th)
        if (.not. (abs(g) < 1.0e-12_dp) .or. .not. (abs(th(5)) < 0.5_dp*pi)) then
            buf = 'no theta5 satisfies the constraint eq. (2) (residual '//sci(g)//'): the '// &
                'cables cannot both be taut at this start; change l, l_prime or the start'
            call set_error(stat, ERR_DECK, trim(buf))
        end if
    contains
        pure real(dp) function beta5(q5)
            real(dp), intent(in) :: q5
            real(dp) :: t(5), bb(5)
            t = th
            t(5) = q5
            bb = beta_coeffs(p, t)
            beta5 = bb(5)
        end function beta5
        pure real(dp) function slope(q5)
            real(dp), intent(in) :: q5
            real(dp) :: b5
            b5 = beta5(q5)
            slope = 0.0_dp
            if (abs(b5) > 1.0e-14_dp) slope = cc/(2.0_dp*b5)
        end function slope
    end subroutine solve_theta5

end module start_pose
