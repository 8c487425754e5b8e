!> The periodic torsion of a platform of elastic cables (module platform_elastic, any
!! n >= 3): the model of a period when four or more cables hold a body off the axis, where
!! inextensible cables are statically indeterminate.  Module platform_measure takes its
!! period (identify on a platform of n >= 4 cables with cg_offset).
!!
!! As module platform_orbit for three inextensible cables: the brake orbit from rest at
!! yaw = rest + amplitude to the half period t_h where yaw' returns to 0, the motion
!! simulated by Radau IIA (module radau; the cables are stiff).  The start is
!! platform_elastic's pe_start: the body turned by the amplitude about the vertical through
!! its mass centre, moved by a sway (s_x, s_y), released at rest with the cables'
!! stretches on the slow motion (their accelerations zero).  The sway is the unknown of the
!! shooting: Newton's method on the residual (x', y') at t_h, its 2 x 2 Jacobian by
!! differences of two more half orbits (sway increments 1e-6 of the rig's size).  The
!! equations are reversible without damping, so that orbit is periodic and the period is
!! 2 t_h.  The stretches' own rates at t_h are not shot: the start on the slow motion
!! excites the stretching modes to O(1/k^2) only (k = &cables stiffness), and the period
!! of the slow motion does not see them.
!!
!! Against the inextensible model the period differs by O(1/k) (the cables stretch by
!! about l/(n k) under the body's weight): at the default k = 1e6 a few parts in 1e7.
module platform_elastic_orbit
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_MODEL
    use text, only: sci, itoa
    use ode_system, only: integrator_t, integrator_stats_t, dense_zero
    use integrators, only: new_integrator, SOLVER_RADAU
    use platform_geometry, only: platform_t, QPSI
    use platform_elastic, only: platform_elastic_t, pe_rest_pose, pe_start, pe_switch, &
                                pe_linearise, CABLE_TAUT, PE_NSTATE
    implicit none
    private

    integer, parameter :: NS = PE_NSTATE
    !> The most integrator steps of a half orbit.
    integer, parameter :: ORBIT_MAX_STEPS = 100000
    !> Newton's most iterations of the shooting.
    integer, parameter :: SHOOT_MAX = 12
    !> The sway increment of the shooting's differences, over the rig's size.
    real(dp), parameter :: SWAY_DEL = 1.0e-6_dp

    !> A periodic torsion of the elastic platform.
    type, public :: elastic_orbit_t
        real(dp) :: th = 0.0_dp                 !! the half period
        real(dp) :: sway(2) = 0.0_dp            !! the start's sway from the turn
        real(dp) :: residual = 0.0_dp           !! max |x'|, |y'| at t_h
        integer :: shooting_iterations = 0
        integer :: steps = 0, rhs_evaluations = 0
    end type elastic_orbit_t

    public :: elastic_torsion_period, elastic_orbit_find, elastic_platform_ready

contains

    !> The elastic platform of pl (every cable's stiffness k = EA/(m g), no damping) at its
    !! elastic rest pose (q_rest), checked stable: ERR_DECK when the cables cannot hold the
    !! body (no rest pose, a slack cable), ERR_MODEL naming the tipping when the rest pose
    !! is unstable (the small oscillations' M^-1 K has an eigenvalue <= 0).
    subroutine elastic_platform_ready(pl, stiffness, el, q_rest, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: stiffness
        type(platform_elastic_t), intent(out) :: el
        real(dp), intent(out) :: q_rest(6)
        type(status_t), intent(out) :: stat
        real(dp) :: omega2(6)
        el%pl = pl
        el%pl%c_v = 0.0_dp
        el%pl%c_q = 0.0_dp
        el%stiffness = stiffness
        el%damping = 0.0_dp
        call pe_rest_pose(el, q_rest, stat)
        if (stat%code /= STATUS_OK) return
        call pe_linearise(el, q_rest, omega2, stat)
        if (stat%code /= STATUS_OK) return
        if (.not. (omega2(1) > 0.0_dp)) then
            call set_error(stat, ERR_MODEL, 'the body tips over on the platform of '// &
                           itoa(pl%n)//' elastic cables (its rest pose is unstable: the '// &
                           'small oscillations'' lowest omega^2 = '//sci(omega2(1))// &
                           '); lower the mass centre (cg_depth)')
            return
        end if
        el%mode(1:el%pl%n) = CABLE_TAUT
    end subroutine elastic_platform_ready

    !> The half orbit from the start turned by amp and moved by sway, at rest, to the time
    !! t_h where yaw' returns to 0; yh the state there.  ERR_MODEL when yaw' does not return
    !! or a cable goes slack on the way.
    subroutine half_orbit(el, q_rest, amp, sway, rtol, atol, what, th, yh, orb, stat)
        type(platform_elastic_t), intent(inout) :: el
        real(dp), intent(in) :: q_rest(6), amp, sway(2), rtol, atol
        character(len=*), intent(in) :: what
        real(dp), intent(out) :: th, yh(NS)
        type(elastic_orbit_t), intent(inout) :: orb
        type(status_t), intent(out) :: stat
        class(integrator_t), allocatable :: s
        type(integrator_stats_t) :: st
        real(dp) :: y0(NS), ydot(NS), y(NS), g(el%pl%n), dir, ta, tb, fa, fb, tmax
        integer :: k, side, iy
        th = 0.0_dp
        yh = 0.0_dp
        call pe_start(el, q_rest, amp, y0, stat, sway=sway)
        if (stat%code /= STATUS_OK) return
        call el%rhs(0.0_dp, y0, ydot, stat)
        if (stat%code /= STATUS_OK) return
        iy = 9                                  ! yaw' (the free coordinates x, y, yaw)
        dir = sign(1.0_dp, ydot(iy))
        if (ydot(iy) == 0.0_dp) then
            call set_error(stat, ERR_MODEL, what//': no torque about the vertical at the '// &
                           'start (zero amplitude?)')
            return
        end if
        call new_integrator(SOLVER_RADAU, s)
        tmax = 1.0e3_dp*2.0_dp*pi/sqrt(el%pl%gravity/el%pl%lscale)
        call s%init(el, 0.0_dp, y0, rtol, [atol], stat, tcrit=tmax)
        if (stat%code /= STATUS_OK) return
        ta = 0.0_dp
        fa = 0.0_dp
        side = 0
        do k = 1, ORBIT_MAX_STEPS
            call s%step(el, stat, tout=tmax)
            if (stat%code /= STATUS_OK) exit
            st = s%stats()
            tb = st%t_current
            call s%dense(tb, 0, y, stat)
            if (stat%code /= STATUS_OK) exit
            call pe_switch(el, y, g, stat)
            if (stat%code /= STATUS_OK) exit
            if (any(.not. (g > 0.0_dp))) then
                call set_error(stat, ERR_MODEL, what//': a cable goes slack at t = '// &
                               sci(tb)//' (the torsion of taut cables ends); lower the '// &
                               'amplitude or move the mass centre towards the axis')
                exit
            end if
            fb = dir*y(iy)
            if (fb > 0.0_dp) then
                side = 1
            else if (side == 1) then
                side = 2
                exit
            end if
            ta = tb
            fa = fb
        end do
        st = s%stats()
        orb%steps = orb%steps + st%steps
        orb%rhs_evaluations = orb%rhs_evaluations + st%rhs_evals
        if (stat%code /= STATUS_OK) return
        if (side /= 2) then
            call set_error(stat, ERR_MODEL, what//': the yaw rate did not return to 0 '// &
                           'within '//itoa(ORBIT_MAX_STEPS)//' steps (no torsion at this '// &
                           'amplitude)')
            return
        end if
        ! the zero of yaw' in [ta, tb]: Illinois' regula falsi on the dense output
        call dense_zero(s, iy, dir, ta, tb, fa, fb, th, stat)
        if (stat%code /= STATUS_OK) return
        call s%dense(th, 0, yh, stat)
    end subroutine half_orbit

    !> The periodic torsion of amplitude amp (rad) of the elastic platform el (ready:
    !! elastic_platform_ready, rest pose q_rest), simulated at rtol, atol (see the module
    !! header).  ERR_MODEL when the shooting does not converge or the model fails.
    subroutine elastic_orbit_find(el, q_rest, amp, rtol, atol, what, orb, stat)
        type(platform_elastic_t), intent(inout) :: el
        real(dp), intent(in) :: q_rest(6), amp, rtol, atol
        character(len=*), intent(in) :: what
        type(elastic_orbit_t), intent(out) :: orb
        type(status_t), intent(out) :: stat
        real(dp) :: sw(2), yh(NS), yp(NS), th, thp, r(2), rp(2), jac(2, 2), dsw(2), det, &
                    tol, del, w, rn, rprev
        integer :: it, j
        if (el%pl%n < 3 .or. el%pl%nf /= 3 .or. any(el%pl%free(1:3) /= [1, 2, QPSI])) then
            call set_error(stat, ERR_DECK, what//': the elastic torsion of a platform of '// &
                           'three or more cables (cables = '//itoa(el%pl%n)//')')
            return
        end if
        w = sqrt(el%pl%gravity/el%pl%lscale)
        ! the residual's floor: the integration's error in the rates
        tol = 1.0e3_dp*rtol*el%pl%lscale*w*max(1.0e-3_dp, abs(amp))
        del = SWAY_DEL*el%pl%lscale
        sw = 0.0_dp
        rprev = huge(1.0_dp)
        do it = 0, SHOOT_MAX
            call half_orbit(el, q_rest, amp, sw, rtol, atol, what, th, yh, orb, stat)
            if (stat%code /= STATUS_OK) return
            r = yh(7:8)
            rn = maxval(abs(r))
            orb%th = th
            orb%sway = sw
            orb%residual = rn
            orb%shooting_iterations = it
            if (rn <= tol) return
            if (it == SHOOT_MAX .or. .not. (0.1_dp*rn < rprev)) exit
            rprev = rn
            do j = 1, 2
                dsw = 0.0_dp
                dsw(j) = del
                call half_orbit(el, q_rest, amp, sw + dsw, rtol, atol, what, thp, yp, orb, &
                                stat)
                if (stat%code /= STATUS_OK) return
                rp = yp(7:8)
                jac(:, j) = (rp - r)/del
            end do
            det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
            if (.not. (abs(det) > 0.0_dp)) exit
            dsw(1) = -(jac(2, 2)*r(1) - jac(1, 2)*r(2))/det
            dsw(2) = -(-jac(2, 1)*r(1) + jac(1, 1)*r(2))/det
            sw = sw + dsw
            if (maxval(abs(dsw)) <= 1.0e-12_dp*el%pl%lscale) then
                call half_orbit(el, q_rest, amp, sw, rtol, atol, what, th, yh, orb, stat)
                if (stat%code /= STATUS_OK) return
                orb%th = th
                orb%sway = sw
                orb%residual = maxval(abs(yh(7:8)))
                orb%shooting_iterations = it + 1
                return
            end if
        end do
        call set_error(stat, ERR_MODEL, what//': no periodic torsion found at amplitude '// &
                       sci(amp/deg)//' deg (the shooting in the sway from the turn about '// &
                       'the mass centre failed): lower the amplitude or move the mass '// &
                       'centre towards the axis')
    end subroutine elastic_orbit_find

    !> The period (the unit of time of pl's g) of the periodic torsion of amplitude amp
    !! (rad) of platform pl (n >= 3, prepared or not) on elastic cables of stiffness k =
    !! EA/(m g), simulated at rtol, atol.
    subroutine elastic_torsion_period(pl, stiffness, amp, rtol, atol, period, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: stiffness, amp, rtol, atol
        real(dp), intent(out) :: period
        type(status_t), intent(out) :: stat
        type(platform_elastic_t) :: el
        type(elastic_orbit_t) :: orb
        real(dp) :: q_rest(6)
        period = 0.0_dp
        call elastic_platform_ready(pl, stiffness, el, q_rest, stat)
        if (stat%code /= STATUS_OK) return
        call elastic_orbit_find(el, q_rest, amp, rtol, atol, 'platform elastic torsion', &
                                orb, stat)
        if (stat%code == STATUS_OK) period = 2.0_dp*orb%th
    end subroutine elastic_torsion_period

end module platform_elastic_orbit
