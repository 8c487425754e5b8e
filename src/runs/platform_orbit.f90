!> The periodic torsion of a platform of three inextensible cables (module platform_model):
!! the brake orbit from rest at yaw = rest + amplitude to the half period where yaw' returns
!! to 0, found by shooting, with its half-period map; and the period of that torsion.
!! Module platform_floquet takes its multipliers; identify on a platform (module
!! platform_measure) its period.  doc/theory.md, "Floquet analysis of a platform's torsion".
!!
!! The platform's equations are reversible: with q -> q, q' -> -q', t -> -t a motion stays a
!! motion (no damping).  A torsion that starts at rest at a turning point and comes to rest
!! again half a period later is therefore periodic, the second half the first run
!! backwards.  For a symmetric platform (a regular polygon, the mass centre on its axis, the
!! vertical a principal axis of the body) it is pure torsion, x = y = 0 throughout.  With the
!! mass centre off the axis the torsion carries a sway with it, and the turning point is
!! not known beforehand: the start at rest with yaw = rest + amplitude has unknown x0, y0
!! (the free coordinates of the origin), and the half period t_h is the time where yaw'
!! returns to 0; Newton's method on the residual (x', y') at t_h (the shooting, half_orbit's
!! sensitivities giving its Jacobian, the moving t_h included) from the turn about the mass
!! centre's vertical (platform_start: the small-amplitude motion), and where that fails by
!! continuation in the offset from the centred body's pure torsion (the offset in
!! CONTINUATION_STEPS steps, doubled up to CONTINUATION_MAX when a step fails).
module platform_orbit
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_MODEL
    use text, only: sci, itoa
    use ode_system, only: integrator_t, integrator_stats_t, dense_zero
    use integrators, only: new_integrator
    use platform_geometry, only: platform_t
    use platform_model, only: platform_sys_t, platform_start, rest_pose
    implicit none
    private

    !> The state of the inextensible trifilar: (x, y, yaw, x', y', yaw').
    integer, parameter, public :: ORBIT_NS = 6
    integer, parameter :: NS = ORBIT_NS
    !> The most integrator steps of a half orbit (as module floquet's FLOQUET_MAX_STEPS).
    integer, parameter :: ORBIT_MAX_STEPS = 20000
    !> Newton's most iterations of the shooting.
    integer, parameter :: SHOOT_MAX = 12
    !> Steps of the continuation in the offset (first try), and most steps.
    integer, parameter :: CONTINUATION_STEPS = 4, CONTINUATION_MAX = 64
    !> The sensitivities' absolute tolerance over the orbit's (per unit of the start's
    !! coordinate scale).
    real(dp), parameter :: SENS_ATOL_SCALE = 100.0_dp

    !> The platform's equations with their Jacobian by forward differences whose increments
    !! follow the coordinates' scales (sqrt(eps) sc_j: the integrators' default increment,
    !! relative to |y_j|, is roundoff where a coordinate passes through 0, as x, y and the
    !! rates do at a turning point): the Jacobian of the orbit's sensitivities.
    type, extends(platform_sys_t) :: orbit_sys_t
        real(dp) :: sc(NS) = 1.0_dp             !! the coordinates' scales
    contains
        procedure :: jacobian => orbit_jacobian
        procedure :: has_jacobian => orbit_has_jacobian
    end type orbit_sys_t

    !> A periodic torsion: its turning points, half period, half-period map, and the work.
    type, public :: platform_orbit_t
        real(dp) :: y0(NS) = 0.0_dp             !! the turning point at t = 0 (at rest)
        real(dp) :: yh(NS) = 0.0_dp             !! the turning point at t_h
        real(dp) :: th = 0.0_dp                 !! the half period
        real(dp) :: n(NS, NS) = 0.0_dp          !! dy(t_h)/dy0 at fixed t_h
        integer :: shooting_iterations = 0      !! Newton's iterations (0: pure torsion)
        integer :: continuation_steps = 0       !! steps in the offset (0: none needed)
        integer :: steps = 0, rhs_evaluations = 0   !! the integrations', all of them
    end type platform_orbit_t

    public :: platform_orbit_find, platform_torsion_period, orbit_flow

contains

    !> The scales of the state's coordinates (lengths; radians; their rates over the
    !! pendulum time sqrt(l/g)).
    pure function state_scales(pl) result(sc)
        type(platform_t), intent(in) :: pl
        real(dp) :: sc(NS)
        real(dp) :: w
        w = sqrt(pl%gravity/pl%lscale)
        sc = [pl%lscale, pl%lscale, 1.0_dp, pl%lscale*w, pl%lscale*w, w]
    end function state_scales

    !> df/dy by forward differences, increments sqrt(eps) sc_j.
    subroutine orbit_jacobian(sys, t, y, dfdy, stat)
        class(orbit_sys_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        real(dp) :: f0(NS), f1(NS), yj(NS), del
        integer :: j
        call sys%rhs(t, y, f0, stat)
        if (stat%code /= STATUS_OK) return
        yj = y
        do j = 1, NS
            del = sqrt(epsilon(1.0_dp))*max(abs(y(j)), sys%sc(j))
            yj(j) = y(j) + del
            del = yj(j) - y(j)
            call sys%rhs(t, yj, f1, stat)
            if (stat%code /= STATUS_OK) return
            dfdy(:, j) = (f1 - f0)/del
            yj(j) = y(j)
        end do
    end subroutine orbit_jacobian

    !> The Jacobian is given (orbit_jacobian).
    logical function orbit_has_jacobian(sys)
        class(orbit_sys_t), intent(in) :: sys
        orbit_has_jacobian = sys%sc(1) > 0.0_dp
    end function orbit_has_jacobian

    !> The orbit from y0 (at rest) to the time t_h where yaw' returns to 0, with its
    !! sensitivities to y0 (the half-period map n = dy(t_h)/dy0 at fixed t_h).  ERR_MODEL when
    !! yaw' does not return within ORBIT_MAX_STEPS steps (no torsion), the integrator's or
    !! the model's failures (a slack cable, a singular chart: ERR_MODEL).
    subroutine half_orbit(pl, y0, rtol, method, what, th, yh, n, nsteps, nrhs, stat)
        type(platform_t), intent(in) :: pl      !! checked, rest pose in q_ref
        real(dp), intent(in) :: y0(NS)
        real(dp), intent(in) :: rtol
        integer, intent(in) :: method
        character(len=*), intent(in) :: what    !! the messages' start
        real(dp), intent(out) :: th, yh(NS), n(NS, NS)
        integer, intent(inout) :: nsteps, nrhs
        type(status_t), intent(out) :: stat
        type(orbit_sys_t) :: sys
        class(integrator_t), allocatable :: s
        type(integrator_stats_t) :: st
        real(dp) :: sc(NS), eye(NS, NS), ydot(NS), dir, ta, tb, fa, fb, y(NS), tmax
        integer :: j, k, side
        sys%pl = pl
        sc = state_scales(pl)
        sys%sc = sc
        eye = 0.0_dp
        do j = 1, NS
            eye(j, j) = 1.0_dp
        end do
        call sys%rhs(0.0_dp, y0, ydot, stat)
        if (stat%code /= STATUS_OK) return
        dir = sign(1.0_dp, ydot(6))             ! yaw' leaves 0 with the sign of yaw''
        if (ydot(6) == 0.0_dp) then
            call set_error(stat, ERR_MODEL, what//': no torque about the vertical '// &
                           'at the start (zero amplitude?)')
            return
        end if
        call new_integrator(method, s)
        ! no stop time: the orbit is stepped until yaw' has come back through 0
        tmax = 1.0e3_dp*2.0_dp*pi/sqrt(pl%gravity/pl%lscale)
        call s%init(sys, 0.0_dp, y0, rtol, rtol*sc, stat, tcrit=tmax)
        if (stat%code /= STATUS_OK) return
        call s%sens_init(sys, eye, stat, error_control=.false., scale=SENS_ATOL_SCALE/sc)
        if (stat%code /= STATUS_OK) return
        ta = 0.0_dp
        fa = 0.0_dp
        side = 0
        do k = 1, ORBIT_MAX_STEPS
            call s%step(sys, stat, tout=tmax)
            if (stat%code /= STATUS_OK) exit
            st = s%stats()
            tb = st%t_current
            call s%dense(tb, 0, y, stat)
            if (stat%code /= STATUS_OK) exit
            fb = dir*y(6)
            if (fb > 0.0_dp) then
                side = 1
            else if (side == 1) then
                side = 2                        ! yaw' came back through 0 in this step
                exit
            end if
            ta = tb
            fa = fb
        end do
        st = s%stats()
        nsteps = nsteps + st%steps
        nrhs = nrhs + st%rhs_evals
        if (stat%code /= STATUS_OK) return
        if (side /= 2) then
            call set_error(stat, ERR_MODEL, what//': the yaw rate did not return '// &
                           'to 0 within '//itoa(ORBIT_MAX_STEPS)//' steps (no torsion at '// &
                           'this amplitude)')
            return
        end if
        ! the zero of yaw' in [ta, tb] (fa > 0 >= fb): Illinois' regula falsi on the dense
        ! output, to roundoff in t
        call dense_zero(s, 6, dir, ta, tb, fa, fb, th, stat)
        if (stat%code /= STATUS_OK) return
        call s%dense(th, 0, yh, stat)
        if (stat%code /= STATUS_OK) return
        call s%sens_dense(th, 0, n, stat)
    end subroutine half_orbit

    !> The accelerations f(y) of the platform's equations.
    subroutine orbit_flow(pl, y, f, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: y(NS)
        real(dp), intent(out) :: f(NS)
        type(status_t), intent(out) :: stat
        type(platform_sys_t) :: sys
        sys%pl = pl
        call sys%rhs(0.0_dp, y, f, stat)
    end subroutine orbit_flow

    !> The shooting: Newton's method on (x', y') at the half period for the start's x0, y0
    !! (yaw fixed at yaw0, at rest), from y0 as given; converged when the residual is below
    !! tol or a correction below 1e-12 of the rig's size.
    subroutine shoot(pl, y0, rtol, method, tol, what, th, yh, n, iters, nsteps, nrhs, ok, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(inout) :: y0(NS)
        real(dp), intent(in) :: rtol, tol
        integer, intent(in) :: method
        character(len=*), intent(in) :: what
        real(dp), intent(out) :: th, yh(NS), n(NS, NS)
        integer, intent(out) :: iters
        integer, intent(inout) :: nsteps, nrhs
        logical, intent(out) :: ok
        type(status_t), intent(out) :: stat
        real(dp) :: f(NS), r(2), jac(2, 2), dp2(2), det, rn, rprev
        integer :: it
        ok = .false.
        iters = 0
        rprev = huge(1.0_dp)
        do it = 0, SHOOT_MAX
            call half_orbit(pl, y0, rtol, method, what, th, yh, n, nsteps, nrhs, stat)
            if (stat%code /= STATUS_OK) return
            r = yh(4:5)
            rn = maxval(abs(r))
            if (rn <= tol) then
                ok = .true.
                return
            end if
            if (it == SHOOT_MAX) return
            if (it > 0) then
                if (.not. (rn < 10.0_dp*rprev)) return     ! diverging
            end if
            rprev = rn
            call orbit_flow(pl, yh, f, stat)
            if (stat%code /= STATUS_OK) return
            if (f(6) == 0.0_dp) return
            ! d(x', y')/d(x0, y0) along yaw'(t_h) = 0: t_h moves by -n(6, j)/f(6)
            jac(:, 1) = n(4:5, 1) - f(4:5)*n(6, 1)/f(6)
            jac(:, 2) = n(4:5, 2) - f(4:5)*n(6, 2)/f(6)
            det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
            if (.not. (abs(det) > 0.0_dp)) return
            dp2(1) = -(jac(2, 2)*r(1) - jac(1, 2)*r(2))/det
            dp2(2) = -(-jac(2, 1)*r(1) + jac(1, 1)*r(2))/det
            y0(1:2) = y0(1:2) + dp2
            iters = it + 1
            if (maxval(abs(dp2)) <= 1.0e-12_dp*pl%lscale) then
                call half_orbit(pl, y0, rtol, method, what, th, yh, n, nsteps, nrhs, stat)
                if (stat%code /= STATUS_OK) return
                ok = .true.
                return
            end if
        end do
    end subroutine shoot

    !> The periodic torsion of amplitude amp (rad) of platform pl (n = 3, inextensible;
    !! checked: check_platform or platform_floquet's platform_point_ready) by method
    !! (SOLVER_LSODA, SOLVER_RADAU) at tolerance rtol: the shooting from the turn about the
    !! mass centre, the continuation in the offset where it fails (see the module header).
    !! ERR_DECK for a platform that is not a trifilar; ERR_MODEL when no periodic torsion is
    !! found or the model fails on the way (a slack cable).  `what` starts the messages.
    subroutine platform_orbit_find(pl, amp, rtol, method, what, orb, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: amp             !! yaw amplitude (rad)
        real(dp), intent(in) :: rtol
        integer, intent(in) :: method
        character(len=*), intent(in) :: what
        type(platform_orbit_t), intent(out) :: orb
        type(status_t), intent(out) :: stat
        real(dp) :: tol, sc(NS), y0(NS), yh(NS), n(NS, NS), th
        integer :: iters
        logical :: ok
        if (pl%n /= 3 .or. pl%nf /= 3) then
            call set_error(stat, ERR_DECK, what//': the torsion of inextensible cables, '// &
                           'n = 3 (cables = '//itoa(pl%n)//')')
            return
        end if
        sc = state_scales(pl)
        ! the residual's floor: the integration's error in the rates
        tol = 1.0e3_dp*rtol*sc(4)*max(1.0e-3_dp, abs(amp))
        call platform_start(pl, amp, y0, stat)
        if (stat%code /= STATUS_OK) return
        call shoot(pl, y0, rtol, method, tol, what, th, yh, n, iters, orb%steps, &
                   orb%rhs_evaluations, ok, stat)
        if (stat%code /= STATUS_OK .and. stat%code /= ERR_MODEL) return
        orb%shooting_iterations = iters
        if (.not. ok .and. any(pl%cg(1:2) /= 0.0_dp)) then
            call continuation(pl, amp, rtol, method, tol, what, y0, th, yh, n, orb, ok, stat)
            if (stat%code /= STATUS_OK .and. stat%code /= ERR_MODEL) return
        end if
        if (.not. ok) then
            call set_error(stat, ERR_MODEL, what//': no periodic torsion found at '// &
                           'amplitude '//sci(amp/deg)//' deg (the shooting from the turn '// &
                           'about the mass centre and the continuation from the centred '// &
                           'body failed): lower the amplitude or move the mass centre '// &
                           'towards the axis')
            return
        end if
        orb%y0 = y0
        orb%yh = yh
        orb%n = n
        orb%th = th
        stat%code = STATUS_OK
    end subroutine platform_orbit_find

    !> The period (the unit of time of pl's g) of the periodic torsion of amplitude amp
    !! (rad) of platform pl (platform_orbit_find).
    subroutine platform_torsion_period(pl, amp, rtol, method, period, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: amp             !! yaw amplitude (rad)
        real(dp), intent(in) :: rtol
        integer, intent(in) :: method
        real(dp), intent(out) :: period
        type(status_t), intent(out) :: stat
        type(platform_orbit_t) :: orb
        period = 0.0_dp
        call platform_orbit_find(pl, amp, rtol, method, 'platform torsion', orb, stat)
        if (stat%code == STATUS_OK) period = 2.0_dp*orb%th
    end subroutine platform_torsion_period

    !> Continuation in the mass centre's offset from the centred body (whose torsion is pure:
    !! its start is known exactly): the offset s cg(1:2), s = 1/K ... 1, each step's start
    !! from the last one's turning point moved as the turn about the mass centre moves, each
    !! solved by the shooting; K doubled when a step fails, up to CONTINUATION_MAX.
    subroutine continuation(pl, amp, rtol, method, tol, what, y0, th, yh, n, res, ok, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: amp, rtol, tol
        integer, intent(in) :: method
        character(len=*), intent(in) :: what
        real(dp), intent(out) :: y0(NS), th, yh(NS), n(NS, NS)
        type(platform_orbit_t), intent(inout) :: res
        logical, intent(out) :: ok
        type(status_t), intent(out) :: stat
        type(platform_t) :: ps
        real(dp) :: yg(NS), dprev(2)
        integer :: kk, i, iters
        kk = CONTINUATION_STEPS
        ok = .false.
        do while (kk <= CONTINUATION_MAX)
            dprev = 0.0_dp
            do i = 0, kk
                ps = pl
                ps%cg(1:2) = pl%cg(1:2)*real(i, dp)/kk
                call rest_pose(ps, stat)
                if (stat%code /= STATUS_OK) exit
                call platform_start(ps, amp, yg, stat)
                if (stat%code /= STATUS_OK) exit
                ! the correction of the turn about the mass centre, carried from the last step
                y0 = yg
                y0(1:2) = yg(1:2) + dprev
                call shoot(ps, y0, rtol, method, tol, what, th, yh, n, iters, res%steps, &
                           res%rhs_evaluations, ok, stat)
                res%shooting_iterations = res%shooting_iterations + iters
                res%continuation_steps = res%continuation_steps + 1
                if (.not. ok) exit
                dprev = y0(1:2) - yg(1:2)
            end do
            if (ok .and. i > kk) return
            ok = .false.
            kk = 2*kk
        end do
        if (stat%code == STATUS_OK) stat%code = ERR_MODEL
    end subroutine continuation

end module platform_orbit
