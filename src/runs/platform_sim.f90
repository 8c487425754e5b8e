!> A simulation of a platform (module platform_rig's platform_case_t) as analysis simulate
!! writes it: the run (module platform_run: the inextensible model checked at every step,
!! or the elastic cables switched between taut and slack) driven over the output times
!! (module run_loop), each row the pose, its rates, every cable's tension, the energy error
!! and the constraint residual (the columns a deck asks for), and the run's figures.
!!
!! The rows.  Time t and every quantity in the deck's units (time in the unit g implies):
!! x, y, z the origin of the body's frame in the support's frame, yaw, pitch, roll its
!! orientation R = Rz(yaw) Ry(pitch) Rx(roll) (rad), their rates, T1 .. Tn the cables'
!! tensions (force; 0 when slack), energy_error E - E(0) (kinetic + m g z_c, + the springs'
!! energy with elastic cables), constraint_residual max_i | |P_i - S_i| - l_i | with l_i
!! the cable's length (inextensible) or, with elastic cables, the master cables' lengths
!! the chart was solved for (the accuracy of the pose solve; the other cables' stretch is
!! their tension).  The columns are those of analysis_groups' platform_columns, in that
!! order: t x y z yaw pitch roll x_dot y_dot z_dot yaw_dot pitch_dot roll_dot T1 .. Tn
!! energy_error constraint_residual.
module platform_sim
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_NUMERIC, ERR_IO
    use text, only: fixed
    use fast_format, only: es_field, f_field
    use output_io, only: all_finite
    use run_loop, only: row_sink_t, stepped_model_t, drive
    use progress, only: pace_t
    use ode_system, only: integrator_stats_t
    use platform_geometry, only: PLATFORM_NMAX, pose_points
    use platform_model, only: platform_motion_t, platform_evaluate
    use platform_elastic, only: pe_motion_t, pe_evaluate, pe_natural_lengths
    use platform_run, only: platform_run_t, platform_run_start, elastic_run_start, &
                            slack_span_t
    use platform_rig, only: platform_case_t
    implicit none
    private

    !> Most columns of a platform's row: t, the pose and its rates, n tensions, two more.
    integer, parameter, public :: PLATFORM_NCOL_MAX = 13 + PLATFORM_NMAX + 2

    !> The figures of a platform's run.
    type, public :: platform_sim_summary_t
        integer :: rows = 0, steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0
        real(dp) :: t_reached = 0.0_dp          !! the last row's time
        real(dp) :: max_abs_yaw = 0.0_dp        !! |yaw - yaw at rest| (rad)
        real(dp) :: max_tilt = 0.0_dp           !! max |pitch - rest|, |roll - rest| (rad)
        real(dp) :: max_sway = 0.0_dp           !! the mass centre's horizontal move from rest
        real(dp) :: max_abs_energy_error = 0.0_dp
        real(dp) :: max_abs_constraint_residual = 0.0_dp
        real(dp) :: min_tension = huge(1.0_dp), max_tension = 0.0_dp
        integer :: cable_switches = 0           !! elastic: switches between taut and slack
        real(dp) :: slack_time(PLATFORM_NMAX) = 0.0_dp   !! elastic: time each cable was slack
        integer :: slack_intervals(PLATFORM_NMAX) = 0
    end type platform_sim_summary_t

    !> The .dat writer of a platform's run (a sink of the run loop).
    type, extends(row_sink_t) :: platform_rows_t
        integer :: unit = -1
        integer :: ncol = 0                     !! columns of this platform
        logical :: want(PLATFORM_NCOL_MAX) = .true.
        real(dp) :: e0 = 0.0_dp                 !! the energy of row 0
        real(dp) :: q_rest(6) = 0.0_dp          !! the rest pose
        real(dp) :: rc_rest(3) = 0.0_dp         !! the mass centre at rest
        type(platform_sim_summary_t) :: sm
        character(len=:), allocatable :: text   !! rows collected, written by blocks
        integer :: used = 0
    contains
        procedure :: take => rows_take
    end type platform_rows_t

    !> Characters of rows collected before one WRITE.
    integer, parameter :: ROW_BLOCK = 32768

    public :: platform_simulate, platform_ncol

contains

    !> Columns of a platform of n cables (platform_columns): 13 + n + 2.
    pure integer function platform_ncol(n)
        integer, intent(in) :: n
        platform_ncol = 15 + n
    end function platform_ncol

    !> Run platform case pc from y0 (platform_case_start) over the output times, writing the
    !! rows of the columns `want` (in platform_columns' order, platform_ncol(n) of them) to
    !! the open unit; the run's figures in sm (steps, right-hand sides and Jacobians of the
    !! whole run, over the elastic model's restarts), the slack intervals (elastic) in spans,
    !! the last integrator's statistics in st.  rtol, atol, method (SOLVER_LSODA or SOLVER_RADAU) of the
    !! integration; `pace` the note of a long run.  ERR_MODEL when a cable goes slack in the
    !! inextensible model or its chart turns singular (platform_run), ERR_NUMERIC for a
    !! non-finite row or the integrator's failure, ERR_IO when a row cannot be written.
    subroutine platform_simulate(pc, y0, times, rtol, atol, method, want, unit, sm, spans, &
                                 st, stat, pace)
        type(platform_case_t), intent(in) :: pc
        real(dp), intent(in) :: y0(:)
        real(dp), intent(in) :: times(0:)       !! output times, from 0
        real(dp), intent(in) :: rtol, atol
        integer, intent(in) :: method
        logical, intent(in) :: want(:)          !! (platform_ncol(n))
        integer, intent(in) :: unit
        type(platform_sim_summary_t), intent(out) :: sm
        type(slack_span_t), allocatable, intent(out) :: spans(:)
        type(integrator_stats_t), intent(out) :: st
        type(status_t), intent(out) :: stat
        type(pace_t), intent(inout), optional :: pace
        type(platform_run_t) :: m
        type(platform_rows_t) :: sink
        real(dp) :: p(3, PLATFORM_NMAX)
        integer :: n, k, ios
        character(len=200) :: msg
        n = pc%pl%n
        sink%unit = unit
        sink%ncol = platform_ncol(n)
        sink%want(1:sink%ncol) = want(1:sink%ncol)
        sink%q_rest = pc%pl%q_ref
        call pose_points(pc%pl, pc%pl%q_ref, p(:, 1:n), sink%rc_rest)
        allocate (character(len=ROW_BLOCK) :: sink%text)
        allocate (spans(0))
        if (pc%elastic) then
            call elastic_run_start(m, pc%el, y0, rtol, atol, method, times(ubound(times, 1)), &
                                   stat)
        else
            call platform_run_start(m, pc%pl, y0, rtol, atol, method, &
                                    times(ubound(times, 1)), stat)
        end if
        if (stat%code /= STATUS_OK) return
        m%remedy = 'raise rtol/atol or shorten tau_end'
        call drive(m, times, sink, stat, pace)
        sm = sink%sm
        st = m%solver%stats()
        sm%steps = m%nsteps
        sm%rhs_evaluations = m%rhs_before + st%rhs_evals
        sm%jacobian_evaluations = m%jac_before + st%jac_evals
        if (m%elastic) then
            sm%cable_switches = m%n_switches
            sm%slack_time(1:n) = m%slack_time(1:n)
            spans = m%spans(1:m%nspans)
            do k = 1, m%nspans
                if (spans(k)%open) spans(k)%t_end = sm%t_reached
                sm%slack_intervals(spans(k)%cable) = sm%slack_intervals(spans(k)%cable) + 1
            end do
        end if
        if (stat%code /= STATUS_OK) return
        if (sink%used > 0) then
            write (unit, '(a)', iostat=ios, iomsg=msg) sink%text(1:sink%used - 1)
            if (ios /= 0) call set_error(stat, ERR_IO, 'cannot write rows of the .dat '// &
                                         'file: '//trim(msg))
        end if
    end subroutine platform_simulate

    !> One row: the motion at t as the model gives it, checked finite, written (the asked
    !! columns: t as F14.6, the others ES24.15E3) and folded into the figures.
    subroutine rows_take(sink, m, k, t, y, stat)
        class(platform_rows_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k                !! row number (0: the start)
        real(dp), intent(in) :: t               !! time of the row
        real(dp), intent(in) :: y(:)            !! state there
        type(status_t), intent(out) :: stat
        real(dp) :: row(PLATFORM_NCOL_MAX), tn(PLATFORM_NMAX), q(6), qd(6), en, res, rc(3)
        real(dp) :: p(3, PLATFORM_NMAX), l0(PLATFORM_NMAX), len_j
        type(platform_motion_t) :: mo
        type(pe_motion_t) :: me
        character(len=14 + 24*(PLATFORM_NCOL_MAX - 1)) :: line
        integer :: n, j, i, nw
        stat%code = STATUS_OK
        select type (m)
        type is (platform_run_t)
            tn = 0.0_dp
            if (m%elastic) then
                n = m%esys%pl%n
                call pe_evaluate(m%esys, y, me, stat)
                if (stat%code /= STATUS_OK) return
                q = me%q
                qd = me%qd
                tn(1:n) = me%tension(1:n)
                en = me%energy
                rc = me%rc
                ! the master cables' lengths against the solved pose
                call pose_points(m%esys%pl, q, p(:, 1:n), rc)
                l0(1:n) = pe_natural_lengths(m%esys)
                res = 0.0_dp
                do j = 1, m%esys%pl%nd
                    i = m%esys%pl%master(j)
                    len_j = l0(i) + y(m%esys%pl%nf + j)
                    res = max(res, abs(norm2(p(:, i) - m%esys%pl%support(:, i)) - len_j))
                end do
            else
                n = m%sys%pl%n
                call platform_evaluate(m%sys%pl, y, mo, stat)
                if (stat%code /= STATUS_OK) return
                q = mo%q
                qd = mo%qd
                do j = 1, m%sys%pl%nd
                    tn(m%sys%pl%master(j)) = mo%tension(j)
                end do
                en = mo%energy
                res = mo%residual
                rc = mo%rc
            end if
        class default
            call set_error(stat, ERR_NUMERIC, 'platform rows: not a platform run')
            return
        end select
        if (k == 0) sink%e0 = en
        row(1) = t
        row(2:7) = q
        row(8:13) = qd
        row(14:13 + n) = tn(1:n)
        row(14 + n) = en - sink%e0
        row(15 + n) = res
        if (.not. all_finite(row(1:sink%ncol))) then
            call set_error(stat, ERR_NUMERIC, 'non-finite result at t = '//fixed(t, 6)// &
                           ': the motion left the range the platform model covers')
            return
        end if
        nw = 0
        if (sink%want(1)) then
            call f_field(row(1), 6, line(1:14))
            nw = 14
        end if
        do j = 2, sink%ncol
            if (.not. sink%want(j)) cycle
            call es_field(row(j), 15, line(nw + 1:nw + 24))
            nw = nw + 24
        end do
        if (sink%used + nw + 1 > ROW_BLOCK) then
            write (sink%unit, '(a)', iostat=i) sink%text(1:sink%used - 1)
            sink%used = 0
            if (i /= 0) then
                call set_error(stat, ERR_IO, 'cannot write rows of the .dat file')
                return
            end if
        end if
        sink%text(sink%used + 1:sink%used + nw) = line(1:nw)
        sink%text(sink%used + nw + 1:sink%used + nw + 1) = achar(10)
        sink%used = sink%used + nw + 1
        associate (s => sink%sm)
            s%rows = s%rows + 1
            s%t_reached = t
            s%max_abs_yaw = max(s%max_abs_yaw, abs(q(4) - sink%q_rest(4)))
            s%max_tilt = max(s%max_tilt, abs(q(5) - sink%q_rest(5)), abs(q(6) - sink%q_rest(6)))
            s%max_sway = max(s%max_sway, norm2(rc(1:2) - sink%rc_rest(1:2)))
            s%max_abs_energy_error = max(s%max_abs_energy_error, abs(row(14 + n)))
            s%max_abs_constraint_residual = max(s%max_abs_constraint_residual, res)
            s%min_tension = min(s%min_tension, minval(tn(1:n)))
            s%max_tension = max(s%max_tension, maxval(tn(1:n)))
        end associate
    end subroutine rows_take

end module platform_sim
