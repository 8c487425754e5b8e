!> Runs of the paper's model for the run loop (module run_loop): kane_run_t steps the
!! pendulum with the integrator of the run (module integrators), explains an integrator's
!! failure, and checks at the end of every internal step that the model still holds
!! (taut cables, regular coordinates); when a check fails, the tau where it first fails is
!! located inside the step.  Any sink of the run loop takes the states: a .dat writer
!! (module simulate), a record (identify), the period finder (period_inversion).
module kane_run
    use kinds, only: dp, deg
    use status, only: status_t, set_error, ERR_MODEL
    use text, only: sci, fixed
    use geometry, only: pendulum_t
    use bifilar_model, only: bifilar_t, motion_t, paper_angles, chart_positions, &
                             step_tensions, NSTATE, sens_dir_t
    use ode_system, only: integrator_t, integrator_stats_t, too_much_accuracy
    use integrators, only: new_integrator
    use run_loop, only: stepped_model_t
    use output_io, only: all_finite
    implicit none
    private

    !> A run of the paper's model for the run loop (module run_loop): the pendulum, its
    !! integrator, the model checked at every step's end (check_validity).
    type, extends(stepped_model_t), public :: kane_run_t
        type(bifilar_t) :: sys                  !! the equations (keep_tensions set)
        class(integrator_t), allocatable :: solver  !! LSODA or Radau (module integrators)
        real(dp) :: th3 = 0.0_dp                !! theta_3 of the last row (branch choice of
                                                !! the paper's angles in messages)
        real(dp) :: t_prev = 0.0_dp             !! last time checked valid
        real(dp) :: t_end = 0.0_dp              !! end of the run (tcrit)
        real(dp) :: rtol = 0.0_dp, atol = 0.0_dp    !! the tolerances (for messages)
        real(dp), allocatable :: s0(:, :)       !! forward sensitivities at the start, if any
    contains
        procedure :: advance => kane_advance
        procedure :: dense => kane_dense
        procedure :: slope_at => kane_slope_at
        procedure :: sens_dot_at => kane_sens_dot_at
        procedure :: sens_dots_at => kane_sens_dots_at
    end type kane_run_t

    public :: kane_run_start, model_checks, tighter_rtol, angle_difference, sway_of, global_rtol

    !> LSODA's local error test at rtol leaves a global error of up to 30 rtol on long
    !! torsions and on b /= b' at 80 degrees (bench_global_error); held to rtol/4 the global
    !! error stays within 10 rtol from rtol 1e-6 to 1e-11 on every simulation deck and on the
    !! general scenes.
    real(dp), parameter, public :: GLOBAL_SHARE = 4.0_dp

    !> |cos theta5| below which line CD counts as vertical: the paper's body angles
    !! theta1, theta4 turn about the same axis there and eq. (38) becomes singular.
    real(dp), parameter, public :: COS5_MIN = 1.0e-3_dp
    !> sin theta2 above which the cable BC counts as horizontal (chart limit).
    real(dp), parameter, public :: SIN2_MAX = 0.9999_dp

contains

    !> Start a run of the paper's model (for the run loop): the pendulum p from the chart
    !! state y0 at tau = 0, by the integrator `method` with tolerances rtol, atol, no step
    !! past t_end; th3 the start's theta_3 (branch of the paper's angles in messages).
    !! The validity of the model is checked at the end of every step (check_validity).
    !! With s0 the run carries forward sensitivities (the integrator's sens_init): column k
    !! starts at s0(:, k) and follows the parameter direction dirs(k) (sens_dir_t; IC only
    !! beyond size(dirs)), scale(k) its size against the state's; sens_dot_at gives their
    !! projections; with sens_error_control they take part in the error test.
    !! With `global` (simulate's runs) the local error is held to rtol/GLOBAL_SHARE (not
    !! below 3e-14), atol likewise, so that the global error follows rtol (within 10 rtol:
    !! tests/bench/bench_global_error.f90); messages quote the rtol and atol given.
    subroutine kane_run_start(m, p, y0, th3, rtol, atol, method, t_end, remedy, stat, s0, &
                              dirs, scale, global, sens_error_control)
        type(kane_run_t), intent(out) :: m      !! the run
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y0(NSTATE)      !! chart state at tau = 0
        real(dp), intent(in) :: th3             !! theta_3 at the start (rad)
        real(dp), intent(in) :: rtol, atol      !! integrator tolerances
        integer, intent(in) :: method           !! SOLVER_LSODA or SOLVER_RADAU
        real(dp), intent(in) :: t_end           !! end of the run (tau), tcrit
        character(len=*), intent(in) :: remedy  !! what to change when a row takes too long
        type(status_t), intent(out) :: stat     !! the integrator's init
        real(dp), intent(in), optional :: s0(:, :)          !! (NSTATE, ns) at tau = 0
        type(sens_dir_t), intent(in), optional :: dirs(:)   !! their parameter directions
        real(dp), intent(in), optional :: scale(:)          !! (ns) their sizes
        logical, intent(in), optional :: global !! hold the global error to rtol
        logical, intent(in), optional :: sens_error_control  !! s0's columns in the error test
        real(dp) :: rt, at
        m%sys%p = p
        m%sys%keep_tensions = .true.            ! for check_validity
        m%y0 = y0
        m%ystep = y0
        m%nsteps = 0
        m%t_cur = 0.0_dp
        m%th3 = th3
        m%t_end = t_end
        m%rtol = rtol
        m%atol = atol
        m%remedy = remedy
        call new_integrator(method, m%solver)
        rt = rtol
        at = atol
        if (present(global)) then
            if (global) then
                rt = global_rtol(rtol)
                at = atol*rt/rtol
            end if
        end if
        call m%solver%init(m%sys, 0.0_dp, y0, rt, [at], stat, tcrit=t_end)
        if (stat%code /= 0 .or. .not. present(s0)) return
        if (present(dirs)) m%sys%dirs = dirs
        m%s0 = s0
        call m%solver%sens_init(m%sys, s0, stat, scale=scale, error_control=sens_error_control)
    end subroutine kane_run_start

    !> g . s_k(t) for each forward sensitivity s_k at t: the start before any step, the
    !! integrator's dense output within the last step (or at its end, for a t beyond it).
    subroutine kane_sens_dot_at(m, t, g, v, stat)
        class(kane_run_t), intent(in) :: m
        real(dp), intent(in) :: t
        real(dp), intent(in) :: g(:)            !! (NSTATE)
        real(dp), intent(out) :: v(:)           !! (ns)
        type(status_t), intent(out) :: stat
        integer :: k
        stat%code = 0
        if (m%nsteps == 0) then
            do k = 1, size(v)
                v(k) = dot_product(g, m%s0(:, k))
            end do
        else
            call m%solver%sens_dense_dot(min(t, m%t_cur), g, v, stat)
        end if
    end subroutine kane_sens_dot_at

    !> g(:, o) . s_k(t) for several vectors at once (v(k, o)), as kane_sens_dot_at on each
    !! column to the last bit, the integrator's dense output shared between them.
    subroutine kane_sens_dots_at(m, t, g, v, stat)
        class(kane_run_t), intent(in) :: m
        real(dp), intent(in) :: t
        real(dp), intent(in) :: g(:, :)         !! (NSTATE, m)
        real(dp), intent(out) :: v(:, :)        !! (ns, m)
        type(status_t), intent(out) :: stat
        integer :: k, o
        stat%code = 0
        if (m%nsteps == 0) then
            do o = 1, size(g, 2)
                do k = 1, size(v, 1)
                    v(k, o) = dot_product(g(:, o), m%s0(:, k))
                end do
            end do
        else
            call m%solver%sens_dense_dots(min(t, m%t_cur), g, v, stat)
        end if
    end subroutine kane_sens_dots_at

    !> The state's derivative f(y) at t (the right-hand side at the start before any step,
    !! the derivative of the integrator's dense output within the last step).
    subroutine kane_slope_at(m, t, f, stat)
        class(kane_run_t), intent(inout) :: m
        real(dp), intent(in) :: t
        real(dp), intent(out) :: f(:)           !! (NSTATE)
        type(status_t), intent(out) :: stat
        stat%code = 0
        if (m%nsteps == 0) then
            call m%sys%rhs(0.0_dp, m%y0, f, stat)
        else
            call m%solver%dense(min(t, m%t_cur), 1, f, stat)
        end if
    end subroutine kane_slope_at

    !> One step of the paper's model: an integrator failure explained (singular coordinates
    !! named, too much accuracy asked), the model checked at the step's end.
    subroutine kane_advance(m, stat)
        class(kane_run_t), intent(inout) :: m
        type(status_t), intent(out) :: stat
        type(integrator_stats_t) :: st
        call m%solver%step(m%sys, stat, tout=m%t_end)
        st = m%solver%stats()
        if (stat%code /= 0) then
            call explain_failure(m%solver, st%t_current, m%th3, stat)
            if (too_much_accuracy(stat)) then
                stat%msg = stat%msg//'; &integration rtol = '//sci(m%rtol, 2)// &
                    ', atol = '//sci(m%atol, 2)//': raise them (rtol >= 3e-14 works '// &
                    'for the paper scenes)'
            end if
            return
        end if
        m%nsteps = m%nsteps + 1
        m%t_cur = st%t_current
        m%h_cur = st%h_last
        call m%solver%dense(st%t_current, 0, m%ystep, stat)
        if (stat%code /= 0) return
        call check_validity(m%sys, m%solver, m%t_prev, st%t_current, m%ystep, m%th3, stat)
        if (stat%code /= 0) return
        m%t_prev = st%t_current
    end subroutine kane_advance

    !> The state at t inside the last step (the integrator's dense output).
    subroutine kane_dense(m, t, y, stat)
        class(kane_run_t), intent(in) :: m
        real(dp), intent(in) :: t
        real(dp), intent(out) :: y(:)
        type(status_t), intent(out) :: stat
        call m%solver%dense(t, 0, y, stat)
    end subroutine kane_dense

    !> The checks that end a run because the model no longer holds (ERR_MODEL): a slack
    !! cable, line CD vertical (singular coordinates), cable BC near the horizontal.
    subroutine model_checks(mo, tau, stat)
        type(motion_t), intent(in) :: mo       !! the motion at tau
        real(dp), intent(in) :: tau            !! time of mo
        type(status_t), intent(out) :: stat    !! ERR_MODEL with a diagnostic, else OK
        stat%code = 0
        if (min(mo%t_bc, mo%t_ad) <= 0.0_dp) then
            call set_error(stat, ERR_MODEL, 'cable goes slack at tau = '//fixed(tau, 6)// &
                ' (T_BC = '//sci(mo%t_bc)//', T_AD = '//sci(mo%t_ad)//' m g): the taut-cable '// &
                'model no longer holds; lower the amplitude or start speed, or lengthen the cables')
        else if (abs(cos(mo%th(5))) < COS5_MIN) then
            ! the texts first: no I/O statement calls a function that does I/O (module text)
            call set_error(stat, ERR_MODEL, 'line CD turns vertical at tau = '//fixed(tau, 6)// &
                ' (theta5 = '//fixed(mo%th(5)/deg, 4)//' deg): the paper''s coordinates '// &
                'theta1, theta4 are singular there; lower the amplitude, tilt or start speed')
        else if (abs(sin(mo%th(2))) > SIN2_MAX) then
            call set_error(stat, ERR_MODEL, 'cable BC swings up to the horizontal at tau = '// &
                fixed(tau, 6)//' (theta2 = '//fixed(mo%th(2)/deg, 4)//' deg): the model of a '// &
                'hanging cable no longer holds; lower the amplitude or start speed')
        end if
    end subroutine model_checks

    !> Model checks at the end of one internal step; when one fails, the tau where it first
    !! fails is located in the step (bisection on the dense output) for the diagnostic.  The
    !! tensions come from what the step computed: those of its last right-hand side (the
    !! corrector's last iterate, which the step's end differs from by less than the
    !! integration error; sys%keep_tensions), else from the state and its derivative in the
    !! integrator's dense output (step_tensions); never from a new solve of eq. (38).
    subroutine check_validity(sys, solver, t0, t1, y1, th3, stat)
        type(bifilar_t), intent(inout) :: sys   !! the pendulum
        class(integrator_t), intent(in) :: solver   !! after the step
        real(dp), intent(in) :: t0, t1          !! previous checked time (valid), step end
        real(dp), intent(in) :: y1(NSTATE)      !! state at t1
        real(dp), intent(in) :: th3             !! theta3 of the last row (branch choice)
        type(status_t), intent(out) :: stat     !! ERR_MODEL (or the evaluation's failure)
        type(status_t) :: s2
        type(motion_t) :: mo
        real(dp) :: a, b, m, lo, ylast(NSTATE)
        integer :: it
        logical :: found
        call sys%last_evaluation(ylast, mo%t_bc, mo%t_ad, found)
        if (found) found = maxval(abs(ylast - y1)) <= 1.0e-6_dp*(1.0_dp + maxval(abs(y1)))
        if (found) then
            mo%th(2) = asin(min(1.0_dp, sqrt(y1(2)**2 + y1(3)**2)))
            mo%th(5) = y1(5)
            stat%code = 0
        else
            call motion_at(t1, mo, stat, .false., y1)
        end if
        if (stat%code /= 0) then
            call explain_failure_at(y1, th3, t1, stat)
            return
        end if
        call model_checks(mo, t1, stat)
        if (stat%code == 0) return
        ! locate the first failure within [max(t0, t1 - h), t1]
        st_h: block
            type(integrator_stats_t) :: st
            st = solver%stats()
            lo = max(t0, t1 - abs(st%h_last))
        end block st_h
        a = lo
        b = t1
        do it = 1, 40
            m = 0.5_dp*(a + b)
            call motion_at(m, mo, s2, .false.)
            if (s2%code == 0) call model_checks(mo, m, s2)
            if (s2%code == 0) then
                a = m
            else
                b = m
            end if
        end do
        call motion_at(b, mo, s2, .true.)
        if (s2%code == 0) call model_checks(mo, b, s2)
        if (s2%code == ERR_MODEL) stat = s2
    contains
        !> What the model checks read at time t of the step (state y when given, else the
        !! dense output; the derivative from the dense output): the tensions, theta5 and
        !! |theta2| (all the paper's angles, branch and sign as the rows', when `angles`).
        subroutine motion_at(t, mt, st, angles, y)
            real(dp), intent(in) :: t
            type(motion_t), intent(out) :: mt
            type(status_t), intent(out) :: st
            logical, intent(in) :: angles
            real(dp), intent(in), optional :: y(NSTATE)
            real(dp) :: yt(NSTATE), ydt(NSTATE)
            if (present(y)) then
                yt = y
            else
                call solver%dense(t, 0, yt, st)
                if (st%code /= 0) return
            end if
            call solver%dense(t, 1, ydt, st)
            if (st%code /= 0) return
            if (angles) then
                call paper_angles(yt, th3, mt%th, mt%thd)
            else
                mt%th(2) = asin(min(1.0_dp, sqrt(yt(2)**2 + yt(3)**2)))
                mt%th(5) = yt(5)
            end if
            call step_tensions(sys, yt, ydt, mt%t_bc, mt%t_ad, st)
        end subroutine motion_at
    end subroutine check_validity

    !> An integrator failure: when the state reached is where the model's coordinates are
    !! singular (line CD vertical, cable BC horizontal), say so (ERR_MODEL).
    subroutine explain_failure(solver, t, th3, stat)
        class(integrator_t), intent(in) :: solver   !! after the failed step
        real(dp), intent(in) :: t               !! time reached
        real(dp), intent(in) :: th3             !! branch choice
        type(status_t), intent(inout) :: stat   !! the failure; replaced when explained
        real(dp) :: yr(NSTATE)
        type(status_t) :: s2
        call solver%dense(t, 0, yr, s2)
        if (s2%code /= 0) return
        call explain_failure_at(yr, th3, t, stat)
    end subroutine explain_failure

    !> As explain_failure, for a given state.
    subroutine explain_failure_at(y, th3, t, stat)
        real(dp), intent(in) :: y(NSTATE)       !! state reached
        real(dp), intent(in) :: th3             !! branch choice
        real(dp), intent(in) :: t               !! its time
        type(status_t), intent(inout) :: stat   !! the failure; replaced when explained
        type(motion_t) :: mo
        real(dp) :: th(5), thd(5)
        if (.not. all_finite(y)) return
        mo = motion_t()
        call paper_angles(y, th3, th, thd)
        mo%th = th
        mo%t_bc = 1.0_dp
        mo%t_ad = 1.0_dp
        if (abs(cos(th(5))) < 10.0_dp*COS5_MIN .or. y(2)**2 + y(3)**2 > SIN2_MAX**2) then
            call model_checks(mo, t, stat)
            if (stat%code == 0) then
                call set_error(stat, ERR_MODEL, 'the equations of motion become singular '// &
                    'at tau = '//fixed(t, 6)//' (theta5 = '//fixed(th(5)/deg, 4)// &
                    ' deg, theta2 = '//fixed(th(2)/deg, 4)//' deg): line CD or cable BC '// &
                    'near their limits; lower the amplitude or start speed')
            end if
        end if
    end subroutine explain_failure_at

    !> The integrator's rtol of a run whose global error follows rtol: rtol/GLOBAL_SHARE,
    !! not below 3e-14 (the smallest the integrator honours) nor above rtol.
    pure real(dp) function global_rtol(rtol) result(r)
        real(dp), intent(in) :: rtol            !! the deck's rtol
        r = min(rtol, max(rtol/GLOBAL_SHARE, 3.0e-14_dp))
    end function global_rtol

    !> The tolerance of the error-estimate rerun: rtol/100, but not below 3e-14 (the
    !! smallest the integrator honours).
    pure real(dp) function tighter_rtol(rtol) result(r)
        real(dp), intent(in) :: rtol            !! the run's rtol
        r = max(rtol/100.0_dp, 3.0e-14_dp)
    end function tighter_rtol

    !> Largest angle difference (rad) between two chart states: theta1, theta4, theta5, and
    !! the direction of the cable BC (|delta sigma| / cos theta2, the angle between the two
    !! directions to first order; regular at theta2 = 0 where theta3 is not defined).
    pure real(dp) function angle_difference(y1, y2) result(da)
        real(dp), intent(in) :: y1(NSTATE), y2(NSTATE)   !! chart states
        real(dp) :: c2
        c2 = sqrt(max(1.0e-12_dp, 1.0_dp - y1(2)**2 - y1(3)**2))
        da = max(abs(y1(1) - y2(1)), abs(y1(4) - y2(4)), abs(y1(5) - y2(5)), &
                 norm2(y1(2:3) - y2(2:3))/c2)
    end function angle_difference

    !> Side-sway Q of a chart state (as in evaluate, without the accelerations).
    pure real(dp) function sway_of(p, y) result(q)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp) :: c(3), dd(3), rs(3), e(3), n(3, 3)
        call chart_positions(p, y, c, dd, rs, e, n)
        q = sqrt(e(1)**2 + (e(2) + 0.5_dp*p%big_b)**2)
    end function sway_of

end module kane_run
