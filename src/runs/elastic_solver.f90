!> The elastic-cable model's integration, by Radau IIA (module radau, the default) or LSODA,
!! with the cables' taut/slack modes as a discrete state.
!!
!! The tension law of elastic_model has a kink where a cable goes slack.  An implicit
!! method's Newton iteration that crosses it does not converge, and at high stiffness the
!! iterates cross it all the time: at k = 1e8 a cable's static stretch is 1e-8 b', inside
!! the position tolerance.  The law decided at each evaluation then costs an implicit
!! method as many steps as an explicit one would take (figures: doc/elastic.md).
!!
!! This driver keeps each cable in a fixed mode (CABLE_TAUT: the smooth spring-dashpot;
!! CABLE_SLACK: no force) during every integrator step, so the implicit method always sees
!! a smooth right-hand side.  After each step it evaluates the switching functions
!! g = min(k eps, k eps + c d|s|/dtau) (elastic_model cable_switch) at the step end.  A cable
!! whose g has left its mode's sign (taut: g > 0; slack: g <= 0) switches: the switch time
!! is located by bisection in the step's dense output, to a few units of roundoff in tau,
!! and the step is cut there.  The new modes take effect, and the integrator restarts from
!! the state at the switch, at the beginning of the next call of step.  At every step end the
!! modes therefore agree with the law decided at each evaluation, and the taut/slack
!! history is known to roundoff in tau: slack_time, slack_intervals and the list of slack
!! intervals (slack_list) are exact rather than sampled.
!!
!! Both integrators serve through the same few calls (init, step, dense, counters): the
!! integrator of the current segment between switches is SOLVER_RADAU (radau_t, which
!! steps over the stiff, lightly damped stretching oscillations) or SOLVER_LSODA (lsoda_t).
!! A Radau segment restarts with the step size the last one would have tried next.
!!
!! In the generalized coordinates (Radau) the switching functions are functions of four
!! state components, the stretches and their rates, and are sampled at NSAMPLE = 8 points
!! of every step, so a slack interval longer than an eighth of a step is seen.  In the
!! maximal coordinates (LSODA) they are checked at the step end only: a switch in and out
!! of one mode inside a single step is not seen there; the error test keeps steps short
!! where the motion of the cables changes quickly.
module elastic_solver
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC, ERR_MODEL, STATUS_OK, GEN_ERR_CHART
    use text, only: sci, fixed
    use bifilar_model, only: motion_t
    use run_loop, only: stepped_model_t
    use ode_system, only: integrator_t, integrator_stats_t, METHOD_BDF
    use lsoda, only: lsoda_t
    use integrators, only: new_integrator, SOLVER_LSODA, SOLVER_RADAU
    use elastic_model, only: elastic_t, elastic_cables_t, elastic_evaluate, cable_switch, &
                             cable_switch_stretched, natural_lengths, &
                             ELASTIC_NSTATE, CABLE_TAUT, CABLE_SLACK
    use elastic_gen, only: elastic_gen_t, gen_to_maximal, maximal_to_gen, chart_quality, &
                           GEN_NSTATE
    implicit none
    private

    !> Most bisection halvings of one switch location (2**-80 of a step is below roundoff).
    integer, parameter :: MAX_BISECT = 80
    !> Default most internal steps in one call of integrate.
    integer, parameter :: DEFAULT_MAX_STEPS = 500000
    !> Chatter: this many switches in a row, each after at most QUICK_STEPS steps of its
    !! mode, stop the integration (the tolerance does not resolve the cables' stretch).
    integer, parameter :: MAX_QUICK_SWITCHES = 100, QUICK_STEPS = 2
    !> The integrators (elastic_solver_t%init method; module integrators).
    public :: SOLVER_LSODA, SOLVER_RADAU
    !> The coordinates of a segment: maximal (elastic_model) or generalized (elastic_gen).
    integer, parameter :: COORDS_MAX = 1, COORDS_GEN = 2
    !> The generalized chart is left below this regularity (elastic_gen chart_quality) and
    !! entered again above QUALITY_ENTER.
    real(dp), parameter :: QUALITY_LEAVE = 0.05_dp, QUALITY_ENTER = 0.1_dp
    !> In the generalized coordinates the switching functions are sampled at this many
    !! equally spaced points of every step (they are functions of four state components).
    integer, parameter :: NSAMPLE = 8

    !> One slack interval of one cable.
    type, public :: slack_interval_t
        integer :: cable = 0                    !! CABLE_BC (1) or CABLE_AD (2)
        real(dp) :: tau_start = 0.0_dp          !! tau at which the cable went slack
        real(dp) :: tau_end = 0.0_dp            !! tau at which it was taut again (when closed)
        logical :: open = .true.                !! still slack (tau_end not yet known)
    end type slack_interval_t

    !> The integration of one elastic run.
    type, public :: elastic_solver_t
        private
        integer :: method = SOLVER_RADAU        ! SOLVER_RADAU or SOLVER_LSODA
        class(integrator_t), allocatable :: it  ! the integrator of the current segment
        logical :: use_gen = .true.             ! Radau: generalized coordinates where regular
        real(dp) :: quality_leave = QUALITY_LEAVE   ! the chart's limits (es_init chart_limits)
        real(dp) :: quality_enter = QUALITY_ENTER
        integer :: n_recoords = 0               ! changes of coordinates (either way)
        logical :: segment_started = .false.    ! a segment ran before (start_segment)
        integer :: coords = COORDS_MAX          ! coordinates of the current segment
        type(elastic_gen_t) :: gen              ! the model in generalized coordinates
        real(dp) :: yg_ref(GEN_NSTATE) = 0.0_dp ! last generalized state (angle branches)
        logical :: have_ref = .false.
        logical :: ready = .false.
        real(dp) :: rtol = 0.0_dp
        real(dp), allocatable :: atol(:)
        logical :: have_tcrit = .false.
        real(dp) :: tcrit = 0.0_dp
        logical :: adams_only = .false.         ! the non-stiff method alone (comparisons)
        real(dp) :: t_now = 0.0_dp              ! end of the last step (or the switch time)
        real(dp) :: t_prev = 0.0_dp             ! start of the last step
        logical :: pending = .false.            ! a switch located, restart at the next step
        real(dp) :: y_switch(ELASTIC_NSTATE) = 0.0_dp
        integer :: mode_next(2) = CABLE_TAUT
        type(integrator_stats_t) :: done             ! counters of the finished LSODA segments
        integer :: n_switches = 0
        integer :: quick = 0                    ! switches in a row after <= QUICK_STEPS steps
        real(dp) :: slack_t(2) = 0.0_dp
        integer :: slack_n(2) = 0
        type(slack_interval_t), allocatable :: intervals(:)
        integer :: n_intervals = 0
    contains
        procedure :: init => es_init
        procedure :: step => es_step
        procedure :: integrate => es_integrate
        procedure :: dense => es_dense
        procedure :: stats => es_stats
        procedure :: switches => es_switches
        procedure :: recoords => es_recoords
        procedure :: slack_time => es_slack_time
        procedure :: slack_intervals => es_slack_intervals
        procedure :: slack_list => es_slack_list
    end type elastic_solver_t

    !> A run of the elastic-cable model for the run loop.
    type, extends(stepped_model_t), public :: elastic_run_t
        type(elastic_t) :: sys
        type(elastic_solver_t) :: solver
        real(dp) :: th_step(5) = 0.0_dp         !! the paper's angles at the last step's end
        real(dp) :: t_end = 0.0_dp
    contains
        procedure :: advance => elastic_advance
        procedure :: dense => elastic_dense
    end type elastic_run_t

    !> model = 'elastic': the largest cable strain accepted (a cable stretched to twice its
    !! natural length is no longer a cable; raise &cables stiffness).
    real(dp), parameter, public :: STRAIN_MAX = 1.0_dp

    public :: initial_modes

contains

    !> The modes the law decided at each evaluation gives at state y: taut where g > 0.
    pure function initial_modes(sys, y) result(mode)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        integer :: mode(2)
        mode = merge(CABLE_TAUT, CABLE_SLACK, cable_switch(sys, y) > 0.0_dp)
    end function initial_modes

    !> Start an elastic integration at (t0, y0): the modes from the state (initial_modes, set
    !! in sys%mode), then the integrator as its init (rtol, atol of size 1 or 13, tcrit).
    subroutine es_init(s, sys, t0, y0, rtol, atol, stat, tcrit, nonstiff_only, method, &
                       maximal_only, chart_limits)
        class(elastic_solver_t), intent(inout) :: s
        type(elastic_t), intent(inout) :: sys   !! the model; its modes are set here
        real(dp), intent(in) :: t0, y0(:), rtol, atol(:)
        type(status_t), intent(out) :: stat     !! the integrator's init's
        real(dp), intent(in), optional :: tcrit !! no step goes past tcrit
        logical, intent(in), optional :: nonstiff_only  !! LSODA: never switch to BDF
                                                !! (the non-stiff method alone, comparisons)
        integer, intent(in), optional :: method !! SOLVER_RADAU (default) or SOLVER_LSODA;
                                                !! nonstiff_only implies SOLVER_LSODA
        logical, intent(in), optional :: maximal_only  !! Radau: never the generalized
                                                !! coordinates (comparisons)
        real(dp), intent(in), optional :: chart_limits(2)  !! Radau: leave the generalized
                                                !! chart below chart_limits(1), enter it above
                                                !! chart_limits(2) (tests; default 0.05, 0.1)
        integer :: j
        s%ready = .false.
        s%adams_only = .false.
        if (present(nonstiff_only)) s%adams_only = nonstiff_only
        s%method = SOLVER_RADAU
        if (present(method)) s%method = method
        if (s%adams_only) s%method = SOLVER_LSODA
        if (allocated(s%it)) deallocate (s%it)     ! start_segment makes the run's integrator
        s%use_gen = s%method == SOLVER_RADAU
        if (present(maximal_only)) s%use_gen = s%use_gen .and. .not. maximal_only
        s%quality_leave = QUALITY_LEAVE
        s%quality_enter = QUALITY_ENTER
        if (present(chart_limits)) then
            s%quality_leave = chart_limits(1)
            s%quality_enter = max(chart_limits(1), chart_limits(2))
        end if
        s%n_recoords = 0
        s%segment_started = .false.
        s%have_ref = .false.
        s%rtol = rtol
        s%atol = atol
        s%have_tcrit = present(tcrit)
        if (present(tcrit)) s%tcrit = tcrit
        s%t_now = t0
        s%t_prev = t0
        s%pending = .false.
        s%done = integrator_stats_t()
        s%n_switches = 0
        s%quick = 0
        s%slack_t = 0.0_dp
        s%slack_n = 0
        s%n_intervals = 0
        if (allocated(s%intervals)) deallocate (s%intervals)
        allocate (s%intervals(8))
        sys%mode = initial_modes(sys, y0)
        do j = 1, 2
            if (sys%mode(j) == CABLE_SLACK) call open_interval(s, j, t0)
        end do
        call start_segment(s, sys, t0, y0, stat, .false., 0.0_dp)
        s%ready = stat%code == STATUS_OK
    end subroutine es_init

    !> Start the integrator of a segment at (t0, y0) (maximal state).  LSODA: bdf = first
    !! step with BDF; Radau: h0 > 0 the first step to try (0: its own estimate), in the
    !! generalized coordinates where the chart is regular enough (QUALITY_ENTER), else in
    !! the maximal ones; Radau gives every coordinate the absolute tolerance atol(1).
    subroutine start_segment(s, sys, t0, y0, stat, bdf, h0)
        type(elastic_solver_t), intent(inout) :: s
        type(elastic_t), intent(inout) :: sys
        real(dp), intent(in) :: t0, y0(:)
        type(status_t), intent(out) :: stat
        logical, intent(in) :: bdf              !! LSODA: first step with BDF
        real(dp), intent(in) :: h0              !! Radau: first step (0: estimated)
        real(dp) :: yg(GEN_NSTATE)
        integer :: before
        before = s%coords
        s%coords = COORDS_MAX
        if (s%use_gen) then
            if (chart_quality(sys, y0) > s%quality_enter) then
                s%gen%el = sys
                if (s%have_ref) then
                    call maximal_to_gen(sys, y0, yg, stat, s%yg_ref)
                else
                    call maximal_to_gen(sys, y0, yg, stat)
                end if
                if (stat%code == STATUS_OK) s%coords = COORDS_GEN
            end if
        end if
        ! a change of coordinates, at the chart's limits, at a cable switch or to retake a
        ! step that met a singularity of the chart
        if (s%segment_started .and. s%coords /= before) s%n_recoords = s%n_recoords + 1
        s%segment_started = .true.
        if (.not. allocated(s%it)) call new_integrator(s%method, s%it)
        select type (it => s%it)
        type is (lsoda_t)
            call it%set_options(start_bdf=bdf .and. .not. s%adams_only, &
                                nonstiff_only=s%adams_only)
        end select
        if (s%coords == COORDS_GEN) then
            s%yg_ref = yg
            s%have_ref = .true.
            if (s%have_tcrit) then
                call s%it%init(s%gen, t0, yg, s%rtol, s%atol(1:1), stat, tcrit=s%tcrit, h0=h0)
            else
                call s%it%init(s%gen, t0, yg, s%rtol, s%atol(1:1), stat, h0=h0)
            end if
        else if (s%method == SOLVER_RADAU .and. s%have_tcrit) then
            call s%it%init(sys, t0, y0, s%rtol, s%atol(1:1), stat, tcrit=s%tcrit, h0=h0)
        else if (s%method == SOLVER_RADAU) then
            call s%it%init(sys, t0, y0, s%rtol, s%atol(1:1), stat, h0=h0)
        else if (s%have_tcrit) then
            call s%it%init(sys, t0, y0, s%rtol, s%atol, stat, tcrit=s%tcrit)
        else
            call s%it%init(sys, t0, y0, s%rtol, s%atol, stat)
        end if
    end subroutine start_segment

    !> The counters of the current segment's integrator.
    function segment_stats(s) result(st)
        type(elastic_solver_t), intent(in) :: s
        type(integrator_stats_t) :: st
        st = s%it%stats()
    end function segment_stats

    !> Solution (k = 0) or its derivative (k = 1; maximal coordinates only) at t in the
    !! current segment's last step, as a maximal state.
    subroutine segment_dense(s, t, k, dky, stat)
        type(elastic_solver_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: dky(:)
        type(status_t), intent(out) :: stat
        real(dp) :: yg(GEN_NSTATE)
        if (s%coords == COORDS_GEN) then
            dky = 0.0_dp
            if (k /= 0) then
                call set_error(stat, ERR_NUMERIC, 'elastic solver dense: only k = 0 in the '// &
                    'generalized coordinates')
                return
            end if
            call s%it%dense(t, 0, yg, stat)
            if (stat%code == STATUS_OK) dky = gen_to_maximal(s%gen%el, yg)
        else
            call s%it%dense(t, k, dky, stat)
        end if
    end subroutine segment_dense

    !> One step: the restart after a switch located by the previous call, one integrator
    !! step, and the location of a switch in it (the step then ends at the switch).  After
    !! it, dense() gives the solution in [t_current - (step), t_current] (stats()%t_current).
    subroutine es_step(s, sys, stat, tout)
        class(elastic_solver_t), intent(inout) :: s
        type(elastic_t), intent(inout) :: sys
        type(status_t), intent(out) :: stat     !! the integrator's failure, with the time
        real(dp), intent(in), optional :: tout  !! as lsoda_t%step, radau_t%step
        type(integrator_stats_t) :: st
        real(dp) :: y(ELASTIC_NSTATE), ys(ELASTIC_NSTATE), t0, t1, a, b, quality
        logical :: sw(2), bdf, near, recoord
        integer :: attempt, i, nsam
        if (.not. s%ready) then
            call set_error(stat, ERR_NUMERIC, 'elastic solver: not initialised')
            return
        end if
        if (s%pending) then
            ! restart in the new modes with the method of the last step before the switch
            ! (BDF on a stiff problem stays BDF; starting BDF at every snap of a cable that
            ! is not stiff costs steps and accuracy: at k = 1e4 without damping, test
            ! 'elastic: slack cables', 18 % more steps and twice the energy error)
            ! (Radau: with the step it would have tried next, at most the last one taken)
            st = segment_stats(s)
            call add_counts(s%done, st)
            bdf = st%method_last == METHOD_BDF
            sys%mode = s%mode_next
            s%pending = .false.
            call start_segment(s, sys, s%t_now, s%y_switch, stat, bdf, &
                               min(abs(st%h_next), abs(st%h_last)))
            if (stat%code /= STATUS_OK) return
        end if
        t0 = s%t_now
        ! tout only sets the direction and scale of a first step; a switch within roundoff of
        ! tout would make it useless (and LSODA refuse it), so it is then left to tcrit
        near = .true.
        if (present(tout)) near = .not. (abs(tout - t0) > 100.0_dp*epsilon(1.0_dp)* &
                                         max(1.0_dp, abs(t0)))
        do attempt = 1, 2
            if (s%coords == COORDS_GEN) then
                s%gen%el = sys
                if (near) then
                    call s%it%step(s%gen, stat)
                else
                    call s%it%step(s%gen, stat, tout)
                end if
            else if (near) then
                call s%it%step(sys, stat)
            else
                call s%it%step(sys, stat, tout)
            end if
            ! a step that ran into a singularity of the generalized chart is taken again in
            ! the maximal coordinates, from the state at t0
            if (stat%code /= GEN_ERR_CHART .or. s%coords /= COORDS_GEN .or. attempt > 1) exit
            st = segment_stats(s)
            call add_counts(s%done, st)
            call segment_dense(s, t0, 0, y, stat)
            if (stat%code /= STATUS_OK) return
            s%use_gen = .false.
            call start_segment(s, sys, t0, y, stat, .false., abs(st%h_next))
            s%use_gen = .true.
            if (stat%code /= STATUS_OK) return
        end do
        if (stat%code /= STATUS_OK) return
        st = segment_stats(s)
        t1 = st%t_current
        ! the switching functions, at NSAMPLE points of the step in the generalized
        ! coordinates (there they are functions of the stretch states), else at its end; the
        ! first switch located by bisection from the sample before it
        nsam = 1
        if (s%coords == COORDS_GEN) nsam = NSAMPLE
        a = t0
        do i = 1, nsam
            b = t1
            if (i < nsam) b = t0 + (t1 - t0)*real(i, dp)/nsam
            call switched_at(s, sys, b, ys, sw, stat)
            if (stat%code /= STATUS_OK) return
            if (any(sw)) exit
            a = b
        end do
        if (any(sw)) call locate_switch(s, sys, a, b, ys, sw, stat)
        if (stat%code /= STATUS_OK) return
        t1 = b
        if (s%coords == COORDS_GEN) then
            y = gen_to_maximal(s%gen%el, ys(1:GEN_NSTATE), quality)
            s%yg_ref = ys(1:GEN_NSTATE)
            recoord = quality < s%quality_leave
        else
            y = ys
            recoord = .false.
            if (s%use_gen) recoord = chart_quality(sys, y) > s%quality_enter
        end if
        s%t_prev = t0
        s%t_now = t1
        call account(s, sys%mode, t0, t1)
        if (recoord .and. .not. any(sw)) then
            ! into or out of the generalized chart: a restart at the step end, modes kept
            s%y_switch = y
            s%mode_next = sys%mode
            s%pending = .true.
        end if
        if (any(sw)) then
            s%y_switch = y
            s%mode_next = sys%mode
            where (sw) s%mode_next = merge(CABLE_SLACK, CABLE_TAUT, sys%mode == CABLE_TAUT)
            s%pending = .true.
            call record_switches(s, sw, s%mode_next, t1)
            if (st%steps <= QUICK_STEPS) then
                s%quick = s%quick + 1
            else
                s%quick = 0
            end if
            if (s%quick >= MAX_QUICK_SWITCHES) call chatter_error(s, sys, stat)
        end if
    contains
        !> Bisection for the first switch in (a, b], the cables sw switching at b with the
        !! state ys there (switched_at): b, ys and sw become the switch's.
        subroutine locate_switch(s, sys, a, b, ys, sw, stat)
            type(elastic_solver_t), intent(inout) :: s
            type(elastic_t), intent(in) :: sys
            real(dp), intent(inout) :: a, b, ys(:)
            logical, intent(inout) :: sw(2)
            type(status_t), intent(out) :: stat
            real(dp) :: m, ym(ELASTIC_NSTATE)
            logical :: swm(2)
            integer :: it
            stat%code = STATUS_OK
            do it = 1, MAX_BISECT
                m = a + 0.5_dp*(b - a)
                if (.not. (m > a .and. m < b)) exit
                call switched_at(s, sys, m, ym, swm, stat)
                if (stat%code /= STATUS_OK) return
                if (any(swm)) then
                    b = m
                    ys = ym
                    sw = swm
                else
                    a = m
                end if
            end do
        end subroutine locate_switch
    end subroutine es_step

    !> The cables chatter between taut and slack: the error test lets the stretch err by
    !! more than the stretch itself.
    subroutine chatter_error(s, sys, stat)
        type(elastic_solver_t), intent(in) :: s
        type(elastic_t), intent(in) :: sys
        type(status_t), intent(inout) :: stat
        character(len=400) :: buf
        write (buf, '(a,i0,a,i0,a,es9.2,a,es9.2,a)') 'the cables switched between '// &
            'taut and slack ', MAX_QUICK_SWITCHES, ' times in a row, each after at most ', &
            QUICK_STEPS, ' steps: the tolerance (rtol = ', s%rtol, ') lets the stretch err '// &
            'by more than a cable''s static stretch (about l/(2 k) = ', &
            0.5_dp*maxval(natural_lengths(sys))/sys%stiffness, ' b''); lower rtol to about '// &
            '1/(2 k) or below, or lower the stiffness'
        call set_error(stat, ERR_NUMERIC, trim(buf))
    end subroutine chatter_error

    !> Cables whose switching function has left the sign of their mode at state y.
    pure function switched(sys, y) result(sw)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        logical :: sw(2)
        real(dp) :: g(2)
        g = cable_switch(sys, y)
        sw = (sys%mode == CABLE_TAUT .and. .not. (g > 0.0_dp)) .or. &
             (sys%mode == CABLE_SLACK .and. g > 0.0_dp)
    end function switched

    !> The cables switched at t in the current segment's last step, and the state there
    !! (generalized coordinates: y(1:GEN_NSTATE), the switching functions from its stretch
    !! states; else the maximal state).
    subroutine switched_at(s, sys, t, y, sw, stat)
        type(elastic_solver_t), intent(in) :: s
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(out) :: y(ELASTIC_NSTATE)
        logical, intent(out) :: sw(2)
        type(status_t), intent(out) :: stat
        y = 0.0_dp
        sw = .false.
        if (s%coords == COORDS_GEN) then
            call s%it%dense(t, 0, y(1:GEN_NSTATE), stat)
            if (stat%code == STATUS_OK) sw = switched_gen(sys, y(1:GEN_NSTATE))
        else
            call segment_dense(s, t, 0, y, stat)
            if (stat%code == STATUS_OK) sw = switched(sys, y)
        end if
    end subroutine switched_at

    !> switched for a generalized state (elastic_gen): the switching functions from its
    !! stretch states.
    pure function switched_gen(sys, yg) result(sw)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: yg(:)
        logical :: sw(2)
        real(dp) :: g(2)
        g = cable_switch_stretched(sys, reshape([yg(5), yg(11), yg(6), yg(12)], [2, 2]))
        sw = (sys%mode == CABLE_TAUT .and. .not. (g > 0.0_dp)) .or. &
             (sys%mode == CABLE_SLACK .and. g > 0.0_dp)
    end function switched_gen

    !> Slack time of the interval [t0, t1] run in the modes `mode`.
    subroutine account(s, mode, t0, t1)
        type(elastic_solver_t), intent(inout) :: s
        integer, intent(in) :: mode(2)
        real(dp), intent(in) :: t0, t1
        where (mode == CABLE_SLACK) s%slack_t = s%slack_t + (t1 - t0)
    end subroutine account

    !> Open or close the slack intervals of the cables switching at t.
    subroutine record_switches(s, sw, mode_new, t)
        type(elastic_solver_t), intent(inout) :: s
        logical, intent(in) :: sw(2)
        integer, intent(in) :: mode_new(2)
        real(dp), intent(in) :: t
        integer :: j, i
        do j = 1, 2
            if (.not. sw(j)) cycle
            s%n_switches = s%n_switches + 1
            if (mode_new(j) == CABLE_SLACK) then
                call open_interval(s, j, t)
            else
                do i = s%n_intervals, 1, -1
                    if (s%intervals(i)%cable == j .and. s%intervals(i)%open) then
                        s%intervals(i)%tau_end = t
                        s%intervals(i)%open = .false.
                        exit
                    end if
                end do
            end if
        end do
    end subroutine record_switches

    subroutine open_interval(s, j, t)
        type(elastic_solver_t), intent(inout) :: s
        integer, intent(in) :: j
        real(dp), intent(in) :: t
        type(slack_interval_t), allocatable :: tmp(:)
        if (s%n_intervals == size(s%intervals)) then
            allocate (tmp(2*size(s%intervals)))
            tmp(1:s%n_intervals) = s%intervals(1:s%n_intervals)
            call move_alloc(tmp, s%intervals)
        end if
        s%n_intervals = s%n_intervals + 1
        s%intervals(s%n_intervals) = slack_interval_t(j, t, t, .true.)
        s%slack_n(j) = s%slack_n(j) + 1
    end subroutine open_interval

    !> Add the counters of a finished segment to the totals.
    pure subroutine add_counts(total, seg)
        type(integrator_stats_t), intent(inout) :: total
        type(integrator_stats_t), intent(in) :: seg
        total%steps = total%steps + seg%steps
        total%rhs_evals = total%rhs_evals + seg%rhs_evals
        total%jac_evals = total%jac_evals + seg%jac_evals
        total%lu_decomps = total%lu_decomps + seg%lu_decomps
        total%conv_failures = total%conv_failures + seg%conv_failures
        total%error_test_failures = total%error_test_failures + seg%error_test_failures
        total%method_switches = total%method_switches + seg%method_switches
    end subroutine add_counts

    !> Solution (k = 0) or its k-th derivative at t in the last step (see step).
    subroutine es_dense(s, t, k, dky, stat)
        class(elastic_solver_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: dky(:)
        type(status_t), intent(out) :: stat
        character(len=160) :: buf
        if (s%pending .and. t > s%t_now + 100.0_dp*epsilon(1.0_dp)*max(1.0_dp, abs(t))) then
            dky = 0.0_dp
            write (buf, '(a,es12.5,a,es12.5)') 'elastic solver dense: tau = ', t, &
                ' lies beyond the cable switch at ', s%t_now
            call set_error(stat, ERR_NUMERIC, trim(buf))
            return
        end if
        call segment_dense(s, t, k, dky, stat)
    end subroutine es_dense

    !> Steps until tout is reached and the state there (dense output).  Forward only.
    subroutine es_integrate(s, sys, tout, y, stat, max_steps)
        class(elastic_solver_t), intent(inout) :: s
        type(elastic_t), intent(inout) :: sys
        real(dp), intent(in) :: tout
        real(dp), intent(out) :: y(:)
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: max_steps  !! most steps in this call (500000)
        integer :: n, nmax
        character(len=160) :: buf
        nmax = DEFAULT_MAX_STEPS
        if (present(max_steps)) nmax = max_steps
        stat%code = STATUS_OK
        y = 0.0_dp
        if (tout < s%t_prev) then
            write (buf, '(a,es12.5,a,es12.5)') 'elastic solver: tout = ', tout, &
                ' lies behind the last step, which starts at ', s%t_prev
            call set_error(stat, ERR_NUMERIC, trim(buf))
            return
        end if
        n = 0
        do while (s%t_now < tout)
            if (n >= nmax) then
                write (buf, '(i0,a,es12.5,a,es12.5)') nmax, ' steps taken without reaching '// &
                    'tau = ', tout, ': stopped at ', s%t_now
                call set_error(stat, ERR_NUMERIC, 'elastic solver: '//trim(buf))
                return
            end if
            call s%step(sys, stat, tout)
            if (stat%code /= STATUS_OK) return
            n = n + 1
        end do
        call s%dense(tout, 0, y, stat)
    end subroutine es_integrate

    !> The integrator's counters summed over the segments between switches, in LSODA's
    !! terms (segment_stats); t_current is the end of the last step (the switch time when a
    !! switch ended it).
    function es_stats(s) result(st)
        class(elastic_solver_t), intent(in) :: s
        type(integrator_stats_t) :: st
        st = segment_stats(s)
        call add_counts(st, s%done)
        st%t_current = s%t_now
    end function es_stats

    !> Number of cable switches (taut -> slack and slack -> taut) so far.
    integer function es_switches(s)
        class(elastic_solver_t), intent(in) :: s
        es_switches = s%n_switches
    end function es_switches

    !> Number of changes between the generalized and the maximal coordinates so far (at
    !! the chart's limits, and steps retaken in the maximal ones at a chart singularity).
    integer function es_recoords(s)
        class(elastic_solver_t), intent(in) :: s
        es_recoords = s%n_recoords
    end function es_recoords

    !> Total slack time of BC (1) and AD (2) up to t_current.
    function es_slack_time(s) result(t)
        class(elastic_solver_t), intent(in) :: s
        real(dp) :: t(2)
        t = s%slack_t
    end function es_slack_time

    !> Number of slack intervals of BC (1) and AD (2) begun up to t_current.
    function es_slack_intervals(s) result(n)
        class(elastic_solver_t), intent(in) :: s
        integer :: n(2)
        n = s%slack_n
    end function es_slack_intervals

    !> The slack intervals so far, in the order they began.
    function es_slack_list(s) result(list)
        class(elastic_solver_t), intent(in) :: s
        type(slack_interval_t), allocatable :: list(:)
        list = s%intervals(1:s%n_intervals)
    end function es_slack_list

    !> One step of the elastic model (elastic_solver: taut/slack switches located), the
    !! sanity limit of the cables' strain checked at its end.
    subroutine elastic_advance(m, stat)
        class(elastic_run_t), intent(inout) :: m
        type(status_t), intent(out) :: stat
        type(integrator_stats_t) :: st
        type(motion_t) :: mo2
        type(elastic_cables_t) :: cab
        call m%solver%step(m%sys, stat, tout=m%t_end)
        st = m%solver%stats()
        if (stat%code /= 0) then
            stat%msg = stat%msg//' at tau = '//fixed(st%t_current, 6)
            return
        end if
        m%nsteps = m%nsteps + 1
        m%t_cur = st%t_current
        m%h_cur = st%h_last
        call m%solver%dense(st%t_current, 0, m%ystep, stat)
        if (stat%code /= 0) return
        ! the cables at the step end: the sanity limit
        call elastic_evaluate(m%sys, m%ystep, m%th_step(3), mo2, stat, m%th_step, cab)
        if (stat%code /= 0) return
        m%th_step = mo2%th
        if (maxval(cab%strain) > STRAIN_MAX) then
            call set_error(stat, ERR_MODEL, 'a cable stretches to more than twice '// &
                'its natural length at tau = '//fixed(st%t_current, 6)//' (strain '// &
                sci(maxval(cab%strain))//'): raise &cables stiffness')
        end if
    end subroutine elastic_advance

    !> The state at t inside the last step (the integrator's dense output).
    subroutine elastic_dense(m, t, y, stat)
        class(elastic_run_t), intent(in) :: m
        real(dp), intent(in) :: t
        real(dp), intent(out) :: y(:)
        type(status_t), intent(out) :: stat
        call m%solver%dense(t, 0, y, stat)
    end subroutine elastic_dense

end module elastic_solver
