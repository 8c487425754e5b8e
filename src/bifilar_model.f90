!> The equations of motion of the bifilar pendulum, Kane & Tseng (1966) eqs. (37)-(43).
!!
!! Two forms of the same equations are assembled here, both as P qddot = Q (eq. (38)) and
!! solved with LAPACK:
!!
!! * paper_accelerations: the paper's coordinates theta_1..theta_5, theta_5 eliminated with
!!   gamma_r = beta_r/beta_5 (eqs. (5)-(6), (31)), the fifth row the twice-differentiated
!!   constraint.  Singular where the paper's coordinates are: theta_2 = 0 (the coefficient of
!!   thddot_3 vanishes), cos(theta_5) = 0, beta_5 = 0.
!! * the integrated form (type bifilar_t): the cable BC's direction is described by its
!!   horizontal components sigma = s2 (c3, s3) instead of (theta_2, theta_3), a chart that is
!!   regular at theta_2 = 0 where the paper's is singular (pure torsion passes through it
!!   twice a period), and the dependent speed is the one with the largest constraint
!!   coefficient, so beta_5 = 0 is harmless.  Everything else (eqs. (8), (14), (19), (24),
!!   (27), (32)-(36)) is the paper's.  The state is
!!   y = (theta1, sigma1, sigma2, theta4, theta5, and their rates), eqs. (40)-(43).
!! Results are reported in the paper's theta_1..theta_5 (paper_angles).
module bifilar_model
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_MODEL, ERR_NUMERIC
    use ode_system, only: ode_system_t
    use geometry, only: pendulum_t, direction_cosines, body_axes, cable_direction, mass_centre, &
                        point_e
    use kinematics, only: omega_coeffs, omega_dot_quadratic, v_coeffs, vdot_coeffs
    use gen_forces, only: generalized_inertia, generalized_forces, inertia_dyadic
    use lapack_wrap, only: la_solve
    implicit none
    private

    integer, parameter, public :: NSTATE = 10   !! y = (q(5), qdot(5))

    !> The pendulum as an ODE system for the integrator.
    type, extends(ode_system_t), public :: bifilar_t
        type(pendulum_t) :: p                   !! scaled parameters
    contains
        procedure :: rhs => bifilar_rhs
    end type bifilar_t

    !> Everything about the motion at one instant (scaled units: b' = m = g = 1).
    type, public :: motion_t
        real(dp) :: th(5) = 0.0_dp              !! theta_1..theta_5 (rad), paper's terms
        real(dp) :: thd(5) = 0.0_dp             !! their rates (rad per unit tau)
        real(dp) :: qdd(5) = 0.0_dp             !! chart accelerations
        real(dp) :: rstar(3) = 0.0_dp, vstar(3) = 0.0_dp, astar(3) = 0.0_dp  !! R*, v, a
        real(dp) :: omega(3) = 0.0_dp, alpha(3) = 0.0_dp  !! angular velocity, acceleration
        real(dp) :: frame(3, 3) = 0.0_dp        !! b_ij of eq. (11)
        real(dp) :: t_bc = 0.0_dp, t_ad = 0.0_dp  !! cable tensions over m g
        real(dp) :: energy = 0.0_dp             !! kinetic + potential energy over m g b'
        real(dp) :: residual = 0.0_dp           !! |AD| - l', over b'
        real(dp) :: q_sway = 0.0_dp             !! Q: horizontal distance of E from the vertical through O
        real(dp) :: q_axis = 0.0_dp             !! horizontal distance of E from the midpoint of CD
    end type motion_t

    !> Positions, partial velocities and convective accelerations at one chart state.
    type :: chart_kin_t
        real(dp) :: n(3, 3), c(3), d(3)         !! direction cosines (8), points C and D
        real(dp) :: jv(3, 5), cv(3)             !! R*: partial velocities, acceleration at qdd = 0
        real(dp) :: jw(3, 5), cw(3), omega(3)   !! the same for the rotation; angular velocity
        real(dp) :: jd(3, 5), cd(3)             !! the same for D
    end type chart_kin_t

    public :: chart_state, paper_angles, chart_accelerations, paper_accelerations, evaluate
    public :: chart_positions, chart_energy, chart_constraint

contains

    !> Right-hand side of eqs. (42)-(43) in the regular chart.
    subroutine bifilar_rhs(sys, t, y, ydot, stat)
        class(bifilar_t), intent(inout) :: sys
        real(dp), intent(in) :: t               !! tau (not used: the system is autonomous)
        real(dp), intent(in) :: y(:)            !! chart state (10)
        real(dp), intent(out) :: ydot(:)        !! its derivative
        type(status_t), intent(out) :: stat
        real(dp) :: qdd(5)
        if (.false.) ydot(1) = t
        call chart_accelerations(sys%p, y, qdd, stat)
        ydot(1:5) = y(6:10)
        ydot(6:10) = qdd
    end subroutine bifilar_rhs

    !> Positions in the chart: C, D, the direction cosines, the cable direction e and the
    !! partial velocities / convective accelerations of R* and D.
    pure subroutine chart_kinematics(p, y, k)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(:)
        type(chart_kin_t), intent(out) :: k
        real(dp) :: th(5), thd(5), e(3), zeta, sd(2), econv(3), vb(3, 5), vdb(3, 5)
        real(dp) :: s4, c4, s5, c5, d4, d5
        integer :: j
        th = [y(1), 0.0_dp, 0.0_dp, y(4), y(5)]
        thd = [y(6), 0.0_dp, 0.0_dp, y(9), y(10)]
        e = cable_direction(y(2:3))
        zeta = -e(3)
        sd = y(7:8)
        k%n = direction_cosines(th)
        k%c = [0.0_dp, -p%big_b, 0.0_dp] + p%big_l*e
        ! the cable: e(sigma) and its second derivative at sigma'' = 0
        econv = [0.0_dp, 0.0_dp, dot_product(sd, sd)/zeta + dot_product(y(2:3), sd)**2/zeta**3]
        ! body part of eqs. (24), (27): columns 1, 4, 5 (theta_2, theta_3 do not enter them)
        vb = v_coeffs(p, th)
        vdb = vdot_coeffs(p, th, thd)
        k%jv(:, 1) = vb(:, 1)
        k%jv(:, 2) = p%big_l*[1.0_dp, 0.0_dp, y(2)/zeta]
        k%jv(:, 3) = p%big_l*[0.0_dp, 1.0_dp, y(3)/zeta]
        k%jv(:, 4) = vb(:, 4)
        k%jv(:, 5) = vb(:, 5)
        k%cv = p%big_l*econv
        do j = 1, 5
            if (j == 2 .or. j == 3) cycle
            k%cv = k%cv + vdb(:, j)*thd(j)
        end do
        k%jw = omega_coeffs(th)
        k%omega = matmul(k%jw, y(6:10))
        k%cw = omega_dot_quadratic(th, thd)
        ! D = C + (c5 s4, c5 c4, s5), eq. (1)
        s4 = sin(th(4)); c4 = cos(th(4)); s5 = sin(th(5)); c5 = cos(th(5))
        d4 = thd(4); d5 = thd(5)
        k%d = k%c + [c5*s4, c5*c4, s5]
        k%jd(:, 1) = 0.0_dp
        k%jd(:, 2:3) = k%jv(:, 2:3)
        k%jd(:, 4) = [c5*c4, -c5*s4, 0.0_dp]
        k%jd(:, 5) = [-s5*s4, -s5*c4, c5]
        k%cd = p%big_l*econv + [-c5*s4*(d4**2 + d5**2) - 2.0_dp*s5*c4*d4*d5, &
                              -c5*c4*(d4**2 + d5**2) + 2.0_dp*s5*s4*d4*d5, -s5*d5**2]
    end subroutine chart_kinematics

    !> Solve P qddot = Q, eq. (38): rows r /= k are Kane's equations (37) for the partial
    !! rates of change of the independent speeds, Jv(:,r) + gamma_r Jv(:,k) (eq. (31)),
    !! with gamma_r = -gradg(r)/gradg(k); row k is the twice-differentiated constraint
    !! gradg . qddot + gconv = 0.  k = `dependent`, or the largest |gradg| when absent.
    subroutine assemble_and_solve(jv, cv, jw, cw, omega, in, gradg, gconv, qdd, stat, dependent)
        real(dp), intent(in) :: jv(3, 5), cv(3), jw(3, 5), cw(3), omega(3), in(3, 3)
        real(dp), intent(in) :: gradg(5), gconv
        real(dp), intent(out) :: qdd(5)
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: dependent
        real(dp) :: pm(5, 5), f(5), gam
        integer :: k, r
        pm = generalized_inertia(jv, jw, in)
        f = generalized_forces(jv, cv, jw, cw, omega, in)
        if (present(dependent)) then
            k = dependent
        else
            k = maxloc(abs(gradg), 1)
        end if
        if (.not. (abs(gradg(k)) > 0.0_dp)) then
            qdd = 0.0_dp
            call set_error(stat, ERR_MODEL, 'constraint gradient vanishes (beta = 0)')
            return
        end if
        do r = 1, 5
            if (r == k) cycle
            gam = -gradg(r)/gradg(k)
            pm(r, :) = pm(r, :) + gam*pm(k, :)
            f(r) = f(r) + gam*f(k)
        end do
        pm(k, :) = gradg
        f(k) = -gconv
        qdd = f
        call la_solve(pm, qdd, stat)
        if (stat%code /= 0) then
            qdd = 0.0_dp
            call set_error(stat, ERR_NUMERIC, 'eq. (38): '//stat%msg)
        end if
    end subroutine assemble_and_solve

    !> Accelerations in the regular chart: qddot = (thddot1, sigma1'', sigma2'', thddot4, thddot5).
    subroutine chart_accelerations(p, y, qdd, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(:)            !! chart state (10)
        real(dp), intent(out) :: qdd(5)         !! chart accelerations
        type(status_t), intent(out) :: stat     !! ERR_MODEL: cable BC horizontal or worse
        type(chart_kin_t) :: k
        if (.not. chart_regular(y)) then
            qdd = 0.0_dp
            call set_error(stat, ERR_MODEL, 'cable BC has swung up to the horizontal (theta2 = 90 deg)')
            return
        end if
        call chart_kinematics(p, y, k)
        call accelerations_from(p, y, k, qdd, stat)
    end subroutine chart_accelerations

    !> The chart is regular while the cable BC hangs below the horizontal.
    pure logical function chart_regular(y)
        real(dp), intent(in) :: y(:)            !! chart state
        chart_regular = y(2)**2 + y(3)**2 < 0.999999_dp
    end function chart_regular

    !> Eq. (38) in the chart from the kinematics k of state y.
    subroutine accelerations_from(p, y, k, qdd, stat)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(:)
        type(chart_kin_t), intent(in) :: k
        real(dp), intent(out) :: qdd(5)
        type(status_t), intent(out) :: stat
        real(dp) :: in(3, 3), gradg(5), vd(3), gconv
        in = inertia_dyadic(body_axes(p, k%n), p%inertia)
        gradg = 2.0_dp*matmul(k%d, k%jd)
        vd = matmul(k%jd, y(6:10))
        gconv = 2.0_dp*(dot_product(vd, vd) + dot_product(k%d, k%cd))
        if (p%stab_rate > 0.0_dp) then
            ! Baumgarte: drift off G = 0 decays at rate a; nothing changes on G = G' = 0
            gconv = gconv + 4.0_dp*p%stab_rate*dot_product(k%d, vd) &
                    + p%stab_rate**2*(dot_product(k%d, k%d) - p%big_lp**2)
        end if
        call assemble_and_solve(k%jv, k%cv, k%jw, k%cw, k%omega, in, gradg, gconv, qdd, stat)
    end subroutine accelerations_from

    !> Accelerations thddot_1..5 from eq. (38) in the paper's own coordinates, theta_5
    !! eliminated as in eqs. (5), (31).  Singular at theta_2 = 0 and beta_5 = 0.
    subroutine paper_accelerations(p, th, thd, thdd, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: th(5), thd(5)   !! angles and rates
        real(dp), intent(out) :: thdd(5)        !! their second derivatives
        type(status_t), intent(out) :: stat
        real(dp) :: n(3, 3), jv(3, 5), cv(3), jw(3, 5), cw(3), omega(3), jd(3, 5), cd(3)
        real(dp) :: in(3, 3), gradg(5), d(3), vd(3), vdc(3, 5), gconv
        real(dp) :: s4, c4, s5, c5
        n = direction_cosines(th)
        jv = v_coeffs(p, th)
        vdc = vdot_coeffs(p, th, thd)
        cv = matmul(vdc, thd)
        jw = omega_coeffs(th)
        omega = matmul(jw, thd)
        cw = omega_dot_quadratic(th, thd)
        s4 = sin(th(4)); c4 = cos(th(4)); s5 = sin(th(5)); c5 = cos(th(5))
        d = [0.0_dp, -p%big_b, 0.0_dp] + p%big_l*[sin(th(2))*cos(th(3)), &
            sin(th(2))*sin(th(3)), -cos(th(2))] + [c5*s4, c5*c4, s5]
        jd = 0.0_dp
        jd(:, 2:3) = jv(:, 2:3)
        jd(:, 4) = [c5*c4, -c5*s4, 0.0_dp]
        jd(:, 5) = [-s5*s4, -s5*c4, c5]
        cd = vdc(:, 2)*thd(2) + vdc(:, 3)*thd(3) &
             + [-c5*s4*(thd(4)**2 + thd(5)**2) - 2.0_dp*s5*c4*thd(4)*thd(5), &
                -c5*c4*(thd(4)**2 + thd(5)**2) + 2.0_dp*s5*s4*thd(4)*thd(5), -s5*thd(5)**2]
        in = inertia_dyadic(body_axes(p, n), p%inertia)
        gradg = 2.0_dp*matmul(d, jd)
        vd = matmul(jd, thd)
        gconv = 2.0_dp*(dot_product(vd, vd) + dot_product(d, cd))
        call assemble_and_solve(jv, cv, jw, cw, omega, in, gradg, gconv, thdd, stat, dependent=5)
    end subroutine paper_accelerations

    !> Chart state from the paper's angles and rates: sigma = s2 (c3, s3).
    pure function chart_state(th, thd) result(y)
        real(dp), intent(in) :: th(5), thd(5)   !! angles (rad) and rates
        real(dp) :: y(10)
        real(dp) :: s2, c2, s3, c3
        s2 = sin(th(2)); c2 = cos(th(2)); s3 = sin(th(3)); c3 = cos(th(3))
        y(1:5) = [th(1), s2*c3, s2*s3, th(4), th(5)]
        y(6:10) = [thd(1), c2*c3*thd(2) - s2*s3*thd(3), c2*s3*thd(2) + s2*c3*thd(3), &
                   thd(4), thd(5)]
    end function chart_state

    !> The paper's angles from a chart state.  theta_2 = +-asin|sigma| and theta_3 are chosen
    !! so that theta_3 is nearest th3_ref (theta_2 changes sign where the cable passes the
    !! vertical, as in eq. (49)); theta_3 is unwrapped to stay continuous.
    pure subroutine paper_angles(y, th3_ref, th, thd)
        real(dp), intent(in) :: y(10)           !! chart state
        real(dp), intent(in) :: th3_ref         !! previous theta_3 (rad)
        real(dp), intent(out) :: th(5), thd(5)  !! angles and rates
        real(dp) :: rho, a3, s2, c2, s3, c3
        rho = sqrt(y(2)**2 + y(3)**2)
        if (rho > 0.0_dp) then
            a3 = atan2(y(3), y(2))
        else
            a3 = th3_ref
        end if
        ! candidates (rho, a3 + 2 pi k) and (-rho, a3 + pi + 2 pi k): nearest to th3_ref
        a3 = a3 + 2.0_dp*pi*anint((th3_ref - a3)/(2.0_dp*pi))
        s2 = rho
        if (abs(a3 - th3_ref) > 0.5_dp*pi) then
            s2 = -rho
            a3 = a3 + sign(pi, th3_ref - a3)
        end if
        th = [y(1), asin(min(1.0_dp, s2)), a3, y(4), y(5)]
        c2 = cos(th(2)); s3 = sin(a3); c3 = cos(a3)
        thd(1) = y(6)
        thd(2) = (c3*y(7) + s3*y(8))/c2
        thd(3) = 0.0_dp
        if (abs(s2) > 0.0_dp) thd(3) = (-s3*y(7) + c3*y(8))/s2
        thd(4:5) = y(9:10)
    end subroutine paper_angles

    !> Positions of C, D, R*, E in the chart (over b', A at the origin).
    pure subroutine chart_positions(p, y, c, d, rstar, e, n)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(10)
        real(dp), intent(out) :: c(3), d(3), rstar(3), e(3), n(3, 3)
        n = direction_cosines([y(1), 0.0_dp, 0.0_dp, y(4), y(5)])
        c = [0.0_dp, -p%big_b, 0.0_dp] + p%big_l*cable_direction(y(2:3))
        d = c - n(3, :)
        rstar = mass_centre(p, c, n)
        e = point_e(p, c, n)
    end subroutine chart_positions

    !> Total energy (kinetic + potential, over m g b') of a chart state.
    pure real(dp) function chart_energy(p, y) result(en)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(10)           !! chart state
        type(chart_kin_t) :: k
        call chart_kinematics(p, y, k)
        en = energy_from(p, y, k)
    end function chart_energy

    !> Kinetic + potential energy from the kinematics k of state y.
    pure real(dp) function energy_from(p, y, k) result(en)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(10)
        type(chart_kin_t), intent(in) :: k
        real(dp) :: v(3), rs(3), in(3, 3)
        in = inertia_dyadic(body_axes(p, k%n), p%inertia)
        v = matmul(k%jv, y(6:10))
        rs = mass_centre(p, k%c, k%n)
        en = 0.5_dp*dot_product(v, v) + 0.5_dp*dot_product(k%omega, matmul(in, k%omega)) + rs(3)
    end function energy_from

    !> The constraint eq. (2) and its rate at a chart state: g = |AD|^2 - L'^2, gdot = dg/dtau.
    pure subroutine chart_constraint(p, y, g, gdot)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(10)           !! chart state
        real(dp), intent(out) :: g, gdot
        type(chart_kin_t) :: k
        call chart_kinematics(p, y, k)
        g = dot_product(k%d, k%d) - p%big_lp**2
        gdot = 2.0_dp*dot_product(k%d, matmul(k%jd, y(6:10)))
    end subroutine chart_constraint

    !> Everything reported about the motion at one instant: angles in the paper's terms,
    !! accelerations, energy, constraint residual, side-sway Q, and the cable tensions from
    !! Newton's law for the body: m a = -m g n3 - T_BC e_BC - T_AD e_AD.
    subroutine evaluate(p, y, th3_ref, mo, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(10)           !! chart state
        real(dp), intent(in) :: th3_ref         !! previous theta_3 (branch choice)
        type(motion_t), intent(out) :: mo
        type(status_t), intent(out) :: stat
        type(chart_kin_t) :: k
        real(dp) :: ebc(3), ead(3), f(3), a11, a12, a22, r1, r2, det, pe(3), mid(3)
        call paper_angles(y, th3_ref, mo%th, mo%thd)
        if (.not. chart_regular(y)) then
            call set_error(stat, ERR_MODEL, 'cable BC has swung up to the horizontal (theta2 = 90 deg)')
            return
        end if
        call chart_kinematics(p, y, k)
        call accelerations_from(p, y, k, mo%qdd, stat)
        if (stat%code /= 0) return
        mo%frame = body_axes(p, k%n)
        mo%rstar = mass_centre(p, k%c, k%n)
        mo%vstar = matmul(k%jv, y(6:10))
        mo%astar = matmul(k%jv, mo%qdd) + k%cv
        mo%omega = k%omega
        mo%alpha = matmul(k%jw, mo%qdd) + k%cw
        mo%energy = energy_from(p, y, k)
        mo%residual = norm2(k%d) - p%big_lp
        ! side-sway: O = (0, -B/2, 0); E below the midpoint of CD
        pe = point_e(p, k%c, k%n)
        mid = k%c - 0.5_dp*k%n(3, :)
        mo%q_sway = sqrt(pe(1)**2 + (pe(2) + 0.5_dp*p%big_b)**2)
        mo%q_axis = sqrt((pe(1) - mid(1))**2 + (pe(2) - mid(2))**2)
        ! tensions: least squares of [ebc ead] T = -(a + n3)
        ebc = cable_direction(y(2:3))
        ead = k%d/norm2(k%d)
        f = -(mo%astar + [0.0_dp, 0.0_dp, 1.0_dp])
        a11 = dot_product(ebc, ebc); a12 = dot_product(ebc, ead); a22 = dot_product(ead, ead)
        r1 = dot_product(ebc, f); r2 = dot_product(ead, f)
        det = a11*a22 - a12**2
        if (abs(det) > 1.0e-14_dp) then
            mo%t_bc = (a22*r1 - a12*r2)/det
            mo%t_ad = (a11*r2 - a12*r1)/det
        else
            ! cables parallel: only their sum is determined; share it equally
            mo%t_bc = 0.5_dp*(r1 + r2)/a11
            mo%t_ad = mo%t_bc
        end if
    end subroutine evaluate

end module bifilar_model
