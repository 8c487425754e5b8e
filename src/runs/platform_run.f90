!> Runs of the multifilar platform for the run loop (module run_loop): the inextensible
!! model (n = 2, 3; module platform_model) with its validity checked at the end of every
!! step, and the elastic model (any n; module platform_elastic) with its cables' taut and
!! slack modes kept fixed within each step and switched where the switching functions
!! change sign.
!!
!! Inextensible.  After every step the cable tensions (those of the step's last right-hand
!! side when it was evaluated at the step's end to 1e-6, else from the state there) must be
!! > 0 and the chart regular (quality >= RUN_MIN_QUALITY); when not, the time where it first fails is located in the
!! step by bisection on the dense output, and the run stops with ERR_MODEL: a slack cable
!! is the end of the inextensible model's validity.
!!
!! Elastic.  As module elastic_solver does for two cables: the switching functions
!! g_i = min(k_i e_i, k_i e_i + c_i l_i') are sampled at NSAMPLE points of every step (for
!! the master cables they are functions of their stretch states alone); where one leaves
!! its mode's sign the switch is located by bisection on the dense output to a few units of
!! roundoff, the step is cut there, and the integrator restarts from the state there in the
!! new modes at the next advance.  The slack time of each cable and the number of switches
!! are counted.  Radau IIA (the default) or LSODA.
module platform_run
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_MODEL, ERR_NUMERIC
    use text, only: sci, fixed, itoa
    use ode_system, only: integrator_t, integrator_stats_t, too_much_accuracy
    use integrators, only: new_integrator, SOLVER_LSODA, SOLVER_RADAU
    use run_loop, only: stepped_model_t
    use platform_geometry, only: platform_t, PLATFORM_NMAX, chart_quality
    use platform_model, only: platform_sys_t, platform_motion_t, platform_evaluate
    use platform_elastic, only: platform_elastic_t, pe_switch, PE_NSTATE, CABLE_TAUT, &
                                CABLE_SLACK
    implicit none
    private

    !> Quality of the chart below which the inextensible run stops (ERR_MODEL).
    real(dp), parameter, public :: RUN_MIN_QUALITY = 1.0e-3_dp
    !> Switching functions sampled at this many points of every elastic step.
    integer, parameter :: NSAMPLE = 8
    !> Most bisection halvings of one switch or failure location.
    integer, parameter :: MAX_BISECT = 80
    !> Chatter: this many switches in a row, each after at most QUICK_STEPS steps, stop the
    !! run (the tolerance does not resolve the cables' stretch).
    integer, parameter :: MAX_QUICK_SWITCHES = 100, QUICK_STEPS = 2

    !> One interval in which a cable was slack (the elastic model): from t_start to t_end,
    !! open while it lasts (t_end then the time the run reached).
    type, public :: slack_span_t
        integer :: cable = 0
        real(dp) :: t_start = 0.0_dp, t_end = 0.0_dp
        logical :: open = .true.
    end type slack_span_t

    !> A run of the platform (either model) for the run loop.
    type, extends(stepped_model_t), public :: platform_run_t
        logical :: elastic = .false.            !! which model
        type(platform_sys_t) :: sys             !! the inextensible model
        type(platform_elastic_t) :: esys        !! the elastic model
        class(integrator_t), allocatable :: solver
        integer :: method = SOLVER_LSODA
        real(dp) :: t_end = 0.0_dp, rtol = 0.0_dp, atol = 0.0_dp
        real(dp) :: t_prev = 0.0_dp             !! start of the last step
        ! -- the elastic model's modes --
        logical :: pending = .false.            !! a switch located: restart at the next advance
        integer :: mode_next(PLATFORM_NMAX) = CABLE_TAUT
        integer :: n_switches = 0               !! mode switches so far
        integer :: quick = 0, steps_in_mode = 0
        real(dp) :: slack_time(PLATFORM_NMAX) = 0.0_dp  !! time each cable was slack
        real(dp) :: first_slack(PLATFORM_NMAX) = 0.0_dp !! the length of its first slack
                                                        !! interval (0 until it ended)
        real(dp), private :: slack_since(PLATFORM_NMAX) = 0.0_dp
        !> every slack interval, in the order they began (nspans of spans)
        type(slack_span_t), allocatable :: spans(:)
        integer :: nspans = 0
        !> right-hand sides and Jacobians of the integrators replaced at the switches (the
        !! run's totals: these plus the present integrator's stats)
        integer :: rhs_before = 0, jac_before = 0
    contains
        procedure :: advance => pr_advance
        procedure :: dense => pr_dense
    end type platform_run_t

    public :: platform_run_start, elastic_run_start

contains

    !> Start a run of the inextensible model of pl (check_platform done) from y0 at t = 0
    !! by `method` (SOLVER_LSODA or SOLVER_RADAU), tolerances rtol, atol, no step past t_end.
    subroutine platform_run_start(m, pl, y0, rtol, atol, method, t_end, stat)
        type(platform_run_t), intent(out) :: m
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: y0(:)
        real(dp), intent(in) :: rtol, atol, t_end
        integer, intent(in) :: method
        type(status_t), intent(out) :: stat
        m%elastic = .false.
        m%sys%pl = pl
        m%sys%keep_tensions = .true.
        m%y0 = y0
        m%ystep = y0
        m%t_end = t_end
        m%rtol = rtol
        m%atol = atol
        m%method = method
        m%remedy = 'lower the amplitude or raise &integration rtol'
        call new_integrator(method, m%solver)
        call m%solver%init(m%sys, 0.0_dp, y0, rtol, [atol], stat, tcrit=t_end)
    end subroutine platform_run_start

    !> Start a run of the elastic model el (its rig prepared, natural lengths set) from
    !! y0 (12) at t = 0; the cables' modes from their switching functions there.
    subroutine elastic_run_start(m, el, y0, rtol, atol, method, t_end, stat)
        type(platform_run_t), intent(out) :: m
        type(platform_elastic_t), intent(in) :: el
        real(dp), intent(in) :: y0(:)
        real(dp), intent(in) :: rtol, atol, t_end
        integer, intent(in) :: method
        type(status_t), intent(out) :: stat
        real(dp) :: g(PLATFORM_NMAX)
        integer :: i, n
        m%elastic = .true.
        m%esys = el
        n = el%pl%n
        m%y0 = y0
        m%ystep = y0
        m%t_end = t_end
        m%rtol = rtol
        m%atol = atol
        m%method = method
        m%remedy = 'raise &integration rtol or the cables'' damping'
        call pe_switch(m%esys, y0, g(1:n), stat)
        if (stat%code /= 0) return
        allocate (m%spans(8))
        do i = 1, n
            m%esys%mode(i) = merge(CABLE_TAUT, CABLE_SLACK, g(i) > 0.0_dp)
            if (m%esys%mode(i) == CABLE_SLACK) call open_span(m, i, 0.0_dp)
        end do
        m%mode_next = m%esys%mode
        call new_integrator(method, m%solver)
        call m%solver%init(m%esys, 0.0_dp, y0, rtol, [atol], stat, tcrit=t_end)
    end subroutine elastic_run_start

    !> One step: the inextensible model checked at the step's end, or the elastic model's
    !! switches located in the step.
    subroutine pr_advance(m, stat)
        class(platform_run_t), intent(inout) :: m
        type(status_t), intent(out) :: stat
        type(integrator_stats_t) :: st
        if (m%elastic .and. m%pending) then
            ! restart at the switch in the new modes
            m%esys%mode = m%mode_next
            st = m%solver%stats()
            m%rhs_before = m%rhs_before + st%rhs_evals
            m%jac_before = m%jac_before + st%jac_evals
            call new_integrator(m%method, m%solver)
            ! the first step estimated afresh: the last mode's steps (a free flight's are
            ! long) say nothing of the new one's (a cable's stretch)
            call m%solver%init(m%esys, m%t_cur, m%ystep, m%rtol, [m%atol], stat, &
                               tcrit=m%t_end)
            if (stat%code /= 0) return
            m%pending = .false.
            m%steps_in_mode = 0
        end if
        m%t_prev = m%t_cur
        if (m%elastic) then
            call m%solver%step(m%esys, stat, tout=m%t_end)
        else
            call m%solver%step(m%sys, stat, tout=m%t_end)
        end if
        st = m%solver%stats()
        if (stat%code /= 0) then
            if (too_much_accuracy(stat)) stat%msg = stat%msg//'; rtol = '//sci(m%rtol, 2)// &
                ': raise it'
            return
        end if
        m%nsteps = m%nsteps + 1
        m%t_cur = st%t_current
        m%h_cur = st%h_last
        call m%solver%dense(m%t_cur, 0, m%ystep, stat)
        if (stat%code /= 0) return
        if (m%elastic) then
            call elastic_switches(m, stat)
        else
            call check_inextensible(m, stat)
        end if
    end subroutine pr_advance

    !> The state at t inside the last step (up to a located switch).
    subroutine pr_dense(m, t, y, stat)
        class(platform_run_t), intent(in) :: m
        real(dp), intent(in) :: t
        real(dp), intent(out) :: y(:)
        type(status_t), intent(out) :: stat
        call m%solver%dense(min(t, m%t_cur), 0, y, stat)
    end subroutine pr_dense

    !> The inextensible model's validity at the step's end: tensions > 0, the chart regular;
    !! the first failure located in the step.
    subroutine check_inextensible(m, stat)
        type(platform_run_t), intent(inout) :: m
        type(status_t), intent(out) :: stat
        real(dp) :: ylast(8), tn(3), a, b, c, y(8), qlast(6)
        logical :: found, ok
        integer :: it, nst
        type(status_t) :: s2
        nst = size(m%ystep)
        stat%code = 0
        call m%sys%last_tensions(ylast(1:nst), tn(1:m%sys%pl%nd), found, qlast)
        if (found) found = maxval(abs(ylast(1:nst) - m%ystep)) <= &
                           1.0e-6_dp*(1.0_dp + maxval(abs(m%ystep)))
        if (found) then
            ok = minval(tn(1:m%sys%pl%nd)) > 0.0_dp .and. &
                 chart_quality(m%sys%pl, qlast) >= RUN_MIN_QUALITY
            if (ok) return
        end if
        call valid_at(m%ystep, ok, stat)
        if (stat%code /= 0 .or. ok) return
        ! locate the first failure in the step
        a = m%t_prev
        b = m%t_cur
        do it = 1, MAX_BISECT
            c = 0.5_dp*(a + b)
            if (.not. (c > a .and. c < b)) exit
            call m%solver%dense(c, 0, y(1:nst), s2)
            if (s2%code /= 0) exit
            call valid_at(y(1:nst), ok, s2)
            if (s2%code /= 0) exit
            if (ok) then
                a = c
            else
                b = c
            end if
        end do
        call m%solver%dense(b, 0, y(1:nst), s2)
        call failure_text(y(1:nst), b, stat)
    contains
        subroutine valid_at(yy, good, st)
            real(dp), intent(in) :: yy(:)
            logical, intent(out) :: good
            type(status_t), intent(out) :: st
            type(platform_motion_t) :: mo
            call platform_evaluate(m%sys%pl, yy, mo, st)
            good = .false.
            if (st%code /= 0) then
                st%code = 0
                return
            end if
            good = minval(mo%tension(1:m%sys%pl%nd)) > 0.0_dp .and. &
                   mo%quality >= RUN_MIN_QUALITY
        end subroutine valid_at
        subroutine failure_text(yy, t, st)
            real(dp), intent(in) :: yy(:), t
            type(status_t), intent(out) :: st
            type(platform_motion_t) :: mo
            integer :: i
            call platform_evaluate(m%sys%pl, yy, mo, st)
            if (st%code /= 0 .or. mo%quality < RUN_MIN_QUALITY) then
                call set_error(st, ERR_MODEL, 'platform: the chart turns singular at t = '// &
                               fixed(t, 6)//' (a cable near the horizontal or the '// &
                               'attachments collinear as the cables see them); lower the '// &
                               'amplitude')
                return
            end if
            i = minloc(mo%tension(1:m%sys%pl%nd), 1)
            call set_error(st, ERR_MODEL, 'platform: cable '//itoa(m%sys%pl%master(i))// &
                           ' goes slack at t = '//fixed(t, 6)//' (tension '// &
                           sci(mo%tension(i))//'): the inextensible model no longer holds; '// &
                           'lower the amplitude or use the elastic model')
        end subroutine failure_text
    end subroutine check_inextensible

    !> The elastic model's switches in the last step: the switching functions sampled at
    !! NSAMPLE points; the first change of a cable's mode located by bisection, the step cut
    !! there (t_cur, ystep) and the restart made pending.
    subroutine elastic_switches(m, stat)
        type(platform_run_t), intent(inout) :: m
        type(status_t), intent(out) :: stat
        real(dp) :: g(PLATFORM_NMAX), y(PE_NSTATE), ta, tb, tc
        integer :: n, k, it, i
        logical :: sw, any_sw
        n = m%esys%pl%n
        stat%code = 0
        m%steps_in_mode = m%steps_in_mode + 1
        any_sw = .false.
        ta = m%t_prev
        do k = 1, NSAMPLE
            tb = m%t_prev + (m%t_cur - m%t_prev)*real(k, dp)/NSAMPLE
            if (k == NSAMPLE) tb = m%t_cur
            call m%solver%dense(tb, 0, y, stat)
            if (stat%code /= 0) return
            call switched(y, sw, stat)
            if (stat%code /= 0) return
            if (sw) then
                any_sw = .true.
                exit
            end if
            ta = tb
        end do
        if (.not. any_sw) then
            call account(m%t_prev, m%t_cur)
            return
        end if
        ! bisection between ta (no switch) and tb (switched)
        do it = 1, MAX_BISECT
            tc = 0.5_dp*(ta + tb)
            if (.not. (tc > ta .and. tc < tb)) exit
            call m%solver%dense(tc, 0, y, stat)
            if (stat%code /= 0) return
            call switched(y, sw, stat)
            if (stat%code /= 0) return
            if (sw) then
                tb = tc
            else
                ta = tc
            end if
        end do
        call m%solver%dense(tb, 0, y, stat)
        if (stat%code /= 0) return
        call pe_switch(m%esys, y, g(1:n), stat)
        if (stat%code /= 0) return
        do i = 1, n
            m%mode_next(i) = merge(CABLE_TAUT, CABLE_SLACK, g(i) > 0.0_dp)
            if (m%mode_next(i) == CABLE_SLACK .and. m%esys%mode(i) == CABLE_TAUT) then
                m%slack_since(i) = tb
                call open_span(m, i, tb)
            end if
            if (m%mode_next(i) == CABLE_TAUT .and. m%esys%mode(i) == CABLE_SLACK) then
                if (m%first_slack(i) == 0.0_dp) m%first_slack(i) = tb - m%slack_since(i)
                call close_span(m, i, tb)
            end if
        end do
        call account(m%t_prev, tb)
        m%t_cur = tb
        m%ystep = y
        m%pending = .true.
        m%n_switches = m%n_switches + 1
        if (m%steps_in_mode <= QUICK_STEPS) then
            m%quick = m%quick + 1
        else
            m%quick = 0
        end if
        if (m%quick >= MAX_QUICK_SWITCHES) then
            call set_error(stat, ERR_NUMERIC, 'platform: the cables chatter between taut '// &
                           'and slack at t = '//fixed(tb, 6)//' ('//itoa(MAX_QUICK_SWITCHES)// &
                           ' switches in a row); lower rtol = '//sci(m%rtol, 2))
        end if
    contains
        subroutine switched(yy, sw_out, st)
            real(dp), intent(in) :: yy(:)
            logical, intent(out) :: sw_out
            type(status_t), intent(out) :: st
            real(dp) :: gg(PLATFORM_NMAX)
            integer :: j
            call pe_switch(m%esys, yy, gg(1:n), st)
            sw_out = .false.
            if (st%code /= 0) return
            do j = 1, n
                if ((m%esys%mode(j) == CABLE_TAUT) .neqv. (gg(j) > 0.0_dp)) sw_out = .true.
            end do
        end subroutine switched
        subroutine account(t0, t1)
            real(dp), intent(in) :: t0, t1
            integer :: j
            do j = 1, n
                if (m%esys%mode(j) == CABLE_SLACK) m%slack_time(j) = m%slack_time(j) + (t1 - t0)
            end do
        end subroutine account
    end subroutine elastic_switches

    !> A slack interval of cable i begins at t.
    subroutine open_span(m, i, t)
        type(platform_run_t), intent(inout) :: m
        integer, intent(in) :: i
        real(dp), intent(in) :: t
        type(slack_span_t), allocatable :: grown(:)
        if (.not. allocated(m%spans)) allocate (m%spans(8))
        if (m%nspans == size(m%spans)) then
            allocate (grown(2*size(m%spans)))
            grown(1:m%nspans) = m%spans(1:m%nspans)
            call move_alloc(grown, m%spans)
        end if
        m%nspans = m%nspans + 1
        m%spans(m%nspans) = slack_span_t(i, t, t, .true.)
    end subroutine open_span

    !> The open slack interval of cable i ends at t.
    subroutine close_span(m, i, t)
        type(platform_run_t), intent(inout) :: m
        integer, intent(in) :: i
        real(dp), intent(in) :: t
        integer :: k
        do k = m%nspans, 1, -1
            if (m%spans(k)%cable == i .and. m%spans(k)%open) then
                m%spans(k)%t_end = t
                m%spans(k)%open = .false.
                return
            end if
        end do
    end subroutine close_span

end module platform_run
