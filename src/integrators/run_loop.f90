!> One stepping driver for every integration that hands out the motion at given times.
!!
!! A simulation writes rows of a .dat file on the uniform grid of &integration dtau_out; the
!! identification fits a model to a record at the record's sample times, in memory; the
!! period of an asymmetric rig is the time to a maximum of theta4, found between steps.  All
!! of them step the same way (STYLE.md, "The run loop"):
!!
!! * the model and its integrator come in as a stepped_model_t: `advance` takes one
!!   internal step of the integrator, explains a failure, and checks the model's validity at
!!   the step's end (taut cables, regular coordinates, a cable's strain), so a run that
!!   leaves the model stops at the step where it happens, not at the next requested time;
!! * the requested times are an array (the uniform grid, or a record's sample times); the
!!   state at each comes from the integrator's dense output within the step that reaches it
!!   (the step's end itself when the time is there), and goes to a row_sink_t: the .dat
!!   writer, an in-memory record, ...;
!! * after every step a sink that asks for it (`watch_steps`) looks at the step
!!   (`after_step`: e.g. locate a maximum of theta4 in it) and may end the run (`done`);
!! * at most MAX_STEPS_PER_ROW internal steps between two requested times, else the run
!!   stops with ERR_NUMERIC and the model's remedy.
!!
!! No routine stops; failures come back in status_t.
module run_loop
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC
    use text, only: sci, fixed
    use progress, only: pace_t
    use unused_arg, only: unused
    implicit none
    private

    !> A model with its integrator, as the driver steps it.  Extensions hold the equations
    !! and the integrator, take one step (`advance`: which sets t_cur, h_cur, ystep and
    !! counts nsteps) and read the integrator's dense output (`dense`); `remedy` says what
    !! to change when a run takes too many steps.
    type, abstract, public :: stepped_model_t
        character(len=:), allocatable :: remedy
        real(dp), allocatable :: y0(:)          !! state at the start
        real(dp), allocatable :: ystep(:)       !! state at the last step's end
        real(dp) :: t_cur = 0.0_dp              !! time reached (the start before any step)
        real(dp) :: h_cur = 0.0_dp              !! last step size
        integer :: nsteps = 0                   !! steps taken
    contains
        procedure(advance_i), deferred :: advance
        procedure(dense_i), deferred :: dense
        procedure :: t_now
        procedure :: h_last
        procedure :: nstate
        procedure :: state_at
    end type stepped_model_t

    !> Where the motion at the requested times goes.
    type, abstract, public :: row_sink_t
        logical :: done = .false.               !! set by the sink to end the run early
        logical :: watch_steps = .false.        !! .true.: after_step is called after each step
    contains
        procedure(take_i), deferred :: take
        procedure :: after_step => no_after_step
    end type row_sink_t

    abstract interface
        !> One internal step; on failure a status whose message says what happened and
        !! where; the model's validity checked at the step's end.
        subroutine advance_i(m, stat)
            import :: stepped_model_t, status_t
            class(stepped_model_t), intent(inout) :: m
            type(status_t), intent(out) :: stat
        end subroutine advance_i
        !> The state at t inside the last step, from the integrator's dense output.
        subroutine dense_i(m, t, y, stat)
            import :: stepped_model_t, dp, status_t
            class(stepped_model_t), intent(in) :: m
            real(dp), intent(in) :: t
            real(dp), intent(out) :: y(:)
            type(status_t), intent(out) :: stat
        end subroutine dense_i
        !> The state y at the k-th requested time t (k from 0).
        subroutine take_i(sink, m, k, t, y, stat)
            import :: row_sink_t, stepped_model_t, dp, status_t
            class(row_sink_t), intent(inout) :: sink
            class(stepped_model_t), intent(inout) :: m
            integer, intent(in) :: k
            real(dp), intent(in) :: t
            real(dp), intent(in) :: y(:)
            type(status_t), intent(out) :: stat
        end subroutine take_i
    end interface

    public :: drive, check_row_budget, falling_zero

    !> Most internal steps between two requested times before the run is given up.
    integer, parameter, public :: MAX_STEPS_PER_ROW = 500000

contains

    !> Step the model and hand its state at each requested time to the sink, in order.
    !! The integration runs to the last requested time (the model's integrator was started
    !! with that tcrit) or until the sink is done.  With `pace` (module progress), a run
    !! that goes on for long says once, on one line, how far it is and how long it will
    !! take at that pace.
    subroutine drive(m, times, sink, stat, pace)
        class(stepped_model_t), intent(inout) :: m  !! started model and integrator
        real(dp), intent(in) :: times(0:)       !! requested times, non-decreasing, from the start
        class(row_sink_t), intent(inout) :: sink    !! where the states go
        type(status_t), intent(out) :: stat     !! the first failure (model, integrator, sink)
        type(pace_t), intent(inout), optional :: pace   !! the note of a long run
        real(dp), allocatable :: y(:)
        real(dp) :: t0, t_reached
        integer :: k, nstep_row
        allocate (y(m%nstate()))
        stat%code = 0
        k = 0
        nstep_row = 0
        t_reached = m%t_now()
        do while (k <= ubound(times, 1))
            if (t_reached < times(k)) then
                if (nstep_row >= MAX_STEPS_PER_ROW) then
                    call check_row_budget(nstep_row, times(k), m%h_last(), m%remedy, stat)
                    exit
                end if
                t0 = t_reached
                call m%advance(stat)
                if (stat%code /= 0) exit
                t_reached = m%t_now()
                nstep_row = nstep_row + 1
                if (present(pace)) call pace%check(t_reached)
                if (sink%watch_steps) then
                    call sink%after_step(m, t0, t_reached, stat)
                    if (stat%code /= 0 .or. sink%done) exit
                end if
                cycle
            end if
            call m%state_at(times(k), y, stat)
            if (stat%code /= 0) exit
            nstep_row = 0
            call sink%take(m, k, times(k), y, stat)
            if (stat%code /= 0 .or. sink%done) exit
            k = k + 1
        end do
    end subroutine drive

    !> The time reached (the start before any step).
    real(dp) function t_now(m)
        class(stepped_model_t), intent(in) :: m
        t_now = m%t_cur
    end function t_now

    !> The last step's size.
    real(dp) function h_last(m)
        class(stepped_model_t), intent(in) :: m
        h_last = m%h_cur
    end function h_last

    !> Number of state components.
    integer function nstate(m)
        class(stepped_model_t), intent(in) :: m
        nstate = size(m%y0)
    end function nstate

    !> The state at t: the start before any step, the step's end at or after it, the dense
    !! output inside the last step.
    subroutine state_at(m, t, y, stat)
        class(stepped_model_t), intent(in) :: m
        real(dp), intent(in) :: t
        real(dp), intent(out) :: y(:)
        type(status_t), intent(out) :: stat
        stat%code = 0
        if (m%nsteps == 0) then
            y = m%y0
        else if (t >= m%t_cur) then
            y = m%ystep
        else
            call m%dense(t, y, stat)
        end if
    end subroutine state_at

    !> Default after_step: nothing.
    subroutine no_after_step(sink, m, t0, t1, stat)
        class(row_sink_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        real(dp), intent(in) :: t0, t1          !! the step: from t0 to t1
        type(status_t), intent(out) :: stat
        call unused(sink)
        call unused(m)
        call unused(t0)
        call unused(t1)
        stat%code = 0
    end subroutine no_after_step

    !> ERR_NUMERIC when the integrator has taken MAX_STEPS_PER_ROW steps without reaching
    !! the next requested time tau; `remedy` says what to change.
    subroutine check_row_budget(nstep_row, tau, h_last, remedy, stat)
        integer, intent(in) :: nstep_row        !! steps since the last row
        real(dp), intent(in) :: tau             !! time of the next row
        real(dp), intent(in) :: h_last          !! last step size
        character(len=*), intent(in) :: remedy
        type(status_t), intent(inout) :: stat
        character(len=200) :: buf
        if (nstep_row < MAX_STEPS_PER_ROW) return
        ! the texts first: no I/O statement calls a function that does I/O (module text)
        write (buf, '(a,i0,a)') 'the integrator took ', MAX_STEPS_PER_ROW, &
            ' steps without reaching tau = '
        call set_error(stat, ERR_NUMERIC, trim(buf)//' '//fixed(tau, 6)//' (last step '// &
                       sci(abs(h_last))//'): '//remedy)
    end subroutine check_row_budget

    !> Where component k of the model's state falls through 0 in the step [t0, t1] (+ at t0,
    !! <= 0 at t1: found), located on the dense output to roundoff by the Illinois variant of
    !! regula falsi; y: the state there.  Not found when the component does not fall so.
    subroutine falling_zero(m, t0, t1, k, found, c, y, stat)
        class(stepped_model_t), intent(inout) :: m
        real(dp), intent(in) :: t0, t1          !! the step
        integer, intent(in) :: k                !! the state's component
        logical, intent(out) :: found
        real(dp), intent(out) :: c              !! the zero (when found)
        real(dp), intent(out) :: y(:)           !! the state at c
        type(status_t), intent(out) :: stat
        real(dp) :: a, b, fa, fb, fc
        integer :: it, side
        found = .false.
        c = t1
        call m%state_at(t1, y, stat)
        if (stat%code /= 0) return
        fb = y(k)
        if (fb > 0.0_dp) return
        call m%state_at(t0, y, stat)
        if (stat%code /= 0) return
        fa = y(k)
        if (.not. (fa > 0.0_dp)) return
        a = t0
        b = t1
        side = 0
        do it = 1, 200
            c = (a*fb - b*fa)/(fb - fa)
            if (.not. (c > a .and. c < b)) c = 0.5_dp*(a + b)
            call m%state_at(c, y, stat)
            if (stat%code /= 0) return
            fc = y(k)
            if (fc > 0.0_dp) then
                a = c
                fa = fc
                if (side == -1) fb = 0.5_dp*fb
                side = -1
            else
                b = c
                fb = fc
                if (side == 1) fa = 0.5_dp*fa
                side = 1
            end if
            if (b - a <= 4.0_dp*epsilon(1.0_dp)*b .or. fc == 0.0_dp) exit
        end do
        found = .true.
    end subroutine falling_zero

end module run_loop
