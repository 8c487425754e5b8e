!> The implementation of analysis simulate (submodule of simulate): the runs of both models
!! through the run loop, the .dat rows and the summary.
submodule (simulate) simulate_impl
    use kinds, only: dp, deg
    use status, only: status_t, set_error, ERR_DECK, ERR_MODEL, ERR_NUMERIC, ERR_IO
    use geometry, only: pendulum_t
    use bifilar_model, only: motion_t, motion_parts_t, evaluate, step_tensions, NSTATE
    use ode_system, only: integrator_t, integrator_stats_t
    use integrators, only: new_integrator, SOLVER_RADAU
    use rig, only: rig_t, make_pendulum, start_state
    use deck_runs, only: rig_of, start_of, method_of, output_times, scene_ready
    use kane_run, only: kane_run_t, kane_run_start, model_checks, tighter_rtol, &
                        angle_difference, sway_of
    use elastic_model, only: elastic_t, elastic_cables_t, elastic_start, elastic_evaluate, &
                             elastic_atol, ELASTIC_NSTATE
    use elastic_solver, only: elastic_solver_t, elastic_run_t, slack_interval_t
    use deck, only: deck_t, deck_echo, OUTPUT_COLUMNS
    use output_io, only: out_files_t, write_kv, all_finite
    use text, only: sci, fixed, itoa
    use unused_arg, only: unused
    use fast_format, only: es_field, f_field
    use run_loop, only: stepped_model_t, row_sink_t, drive, check_row_budget
    use progress, only: pace_t
    implicit none

    !> The .dat columns (deck OUTPUT_COLUMNS, in that order) and the positions of those that
    !! decide what a row computes.
    integer, parameter :: NCOL = 17

    integer, parameter :: COL_Q = 12, COL_Q_AXIS = 13, COL_T_BC = 14, COL_T_AD = 15, &
        COL_ENERGY = 16, COL_RESIDUAL = 17

    !> Width of a row: tau (F14.6) and 16 reals (ES24.15E3)
    integer, parameter :: ROW_WIDTH = 14 + 24*(NCOL - 1)

    !> Characters of rows collected before one WRITE (row_block_t)
    integer, parameter :: ROW_BLOCK = 32768

    !> Rows of a .dat file collected into blocks of up to ROW_BLOCK characters, each written
    !! by one WRITE (the rows joined by newlines): the run-time library's cost per statement
    !! and the system calls are paid per block, not per row.
    type :: row_block_t
        integer :: unit = -1                    !! the open .dat unit
        integer :: used = 0                     !! characters collected
        character(len=ROW_BLOCK) :: text
    end type row_block_t

    !> The .dat writer of a simulation of the paper's model (a sink of the run loop).
    type, extends(row_sink_t) :: kane_dat_sink_t
        type(row_block_t) :: rb                 !! rows of the open .dat file
        logical :: want(NCOL) = .true.          !! the columns written
        type(motion_parts_t) :: parts           !! what a row computes
        type(run_summary_t) :: sm               !! figures of the run
        real(dp) :: e0 = 0.0_dp                 !! energy of row 0
        logical :: error_estimate = .false.     !! rerun at rtol/100 in step (solver2)
        class(integrator_t), allocatable :: solver2
    contains
        procedure :: take => kane_dat_take
    end type kane_dat_sink_t

    !> The .dat writer of a simulation of the elastic model.
    type, extends(row_sink_t) :: elastic_dat_sink_t
        type(row_block_t) :: rb
        logical :: want(NCOL) = .true.
        type(run_summary_t) :: sm
        real(dp) :: e0 = 0.0_dp
        real(dp) :: th_row(5) = 0.0_dp          !! the paper's angles of the last row
        logical :: error_estimate = .false.
        type(elastic_t) :: sys2                 !! the rerun's own system (cable modes)
        type(elastic_solver_t) :: solver2
    contains
        procedure :: take => elastic_dat_take
    end type elastic_dat_sink_t

contains



    !> The preconditions (deck_runs's scene_ready).
    module procedure simulate_ready
        call unused(self)
        call scene_ready(d, stat)
    end procedure simulate_ready

    !> The run (run_simulation into the run's files).
    module procedure simulate_run
        call unused(options)
        call run_simulation(d, outdir, self%sm, stat, files=files)
    end procedure simulate_run

    !> ' simulate cpu T s, steps N, rhs N, max |dE| E, max |residual| R;'
    module procedure simulate_summary
        call unused(d)
        s = ' simulate cpu '//fixed(self%sm%cpu_seconds, 4)//' s, steps '// &
            itoa(self%sm%steps)//', rhs '//itoa(self%sm%rhs_evaluations)//', max |dE| '// &
            sci(self%sm%max_abs_energy_error, 2)//', max |residual| '// &
            sci(self%sm%max_abs_constraint_residual, 2)//';'
    end procedure simulate_summary

    !> Run the simulation of a deck and write OUTDIR/NAME.dat and OUTDIR/NAME.summary.
    !! With `files` the files join the run's others there (the caller commits them all
    !! together, or removes them all on failure); without it they are committed at the end
    !! of a successful run and removed on failure.
    module procedure run_simulation
        type(out_files_t), target :: own
        type(out_files_t), pointer :: fs
        fs => own
        if (present(files)) fs => files
        if (trim(d%scene%model) == 'elastic') then
            call run_elastic(d, outdir, fs, sm, stat)
        else
            call simulate_kane(d, outdir, fs, sm, stat)
        end if
        if (present(files)) return
        if (stat%code == 0) call own%commit(stat)
        if (stat%code /= 0) call own%discard()
    end procedure run_simulation

    !> run_simulation for the paper's model (model = 'kane'): the run loop (module run_loop)
    !! with the paper's model (kane_run_t) and the .dat writer (kane_dat_sink_t).
    subroutine simulate_kane(d, outdir, fs, sm, stat)
        type(deck_t), intent(in) :: d           !! the deck
        character(len=*), intent(in) :: outdir  !! output directory
        type(out_files_t), intent(inout) :: fs  !! the run's files
        type(run_summary_t), intent(out) :: sm  !! figures of the run
        type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL or ERR_IO
        type(kane_run_t) :: m
        type(kane_dat_sink_t) :: sink
        type(pace_t) :: pace
        type(pendulum_t) :: p
        real(dp) :: y(NSTATE), th0(5), t_cpu0, rt2
        real(dp), allocatable :: times(:)
        character(len=:), allocatable :: sumpath
        integer :: u

        call make_pendulum(rig_of(d), p, stat)
        if (stat%code /= 0) return
        call start_state(start_of(d), p, y, th0, stat)
        if (stat%code /= 0) return
        ! compute only what the asked columns need (the model checks need only the tensions'
        ! signs: from the integrator's derivative when T_BC, T_AD are not asked)
        call column_mask(d, sink%want)
        sink%parts%accelerations = sink%want(COL_T_BC) .or. sink%want(COL_T_AD)
        sink%parts%energy = sink%want(COL_ENERGY)
        sink%parts%residual = sink%want(COL_RESIDUAL)
        sink%parts%sway = sink%want(COL_Q) .or. sink%want(COL_Q_AXIS)
        sink%sm%have_sway = sink%parts%sway
        sink%sm%have_energy = sink%parts%energy
        sink%sm%have_residual = sink%parts%residual

        call open_dat(d, outdir, '', fs, u, sumpath, stat)
        if (stat%code /= 0) return
        sink%rb%unit = u

        call cpu_time(t_cpu0)
        ! tcrit = tau_end: no step goes past the end, so every step end checked lies in the run
        sink%sm%method = merge('radau', 'lsoda', method_of(d) == SOLVER_RADAU)
        call kane_run_start(m, p, y, th0(3), d%integration%rtol, d%integration%atol, &
                            method_of(d), d%integration%tau_end, &
                            'raise rtol/atol or shorten tau_end', stat, global=.true.)
        if (stat%code /= 0) return
        if (d%integration%error_estimate) then
            ! the same run at a tolerance 100 times tighter, in step with the rows
            rt2 = tighter_rtol(d%integration%rtol)
            call new_integrator(method_of(d), sink%solver2)
            call sink%solver2%init(m%sys, 0.0_dp, y, rt2, &
                                   [d%integration%atol*rt2/d%integration%rtol], stat, &
                                   tcrit=d%integration%tau_end)
            if (stat%code /= 0) return
            sink%error_estimate = .true.
            sink%sm%error_estimate_rtol = rt2
            sink%sm%error_estimate_theta = 0.0_dp
            sink%sm%error_estimate_q = 0.0_dp
        end if
        call output_times(d, times)
        call pace%start('bifilar: note: '//d%path//': simulate', 0.0_dp, d%integration%tau_end, &
                        'tau')
        call drive(m, times, sink, stat, pace)
        if (stat%code == 0) call flush_rows(sink%rb, stat)
        sm = sink%sm
        call finish_run(m%solver%stats(), t_cpu0, fs, u, sm, stat)
        if (stat%code /= 0) return

        call write_summary(d, sm, fs, sumpath, stat)
    end subroutine simulate_kane

    !> One row of the paper's model's .dat file: the motion at tau as the asked columns
    !! need it (the tensions from the integrator's derivative when T_BC, T_AD are not
    !! asked), the row written and folded into the summary, and the error-estimate rerun
    !! brought to tau.
    subroutine kane_dat_take(sink, m, k, t, y, stat)
        class(kane_dat_sink_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k                !! row number (0: the start)
        real(dp), intent(in) :: t               !! tau of the row
        real(dp), intent(in) :: y(:)            !! chart state there
        type(status_t), intent(out) :: stat
        type(motion_t) :: mo
        real(dp) :: ydot(NSTATE), y2(NSTATE), t_e0
        stat%code = 0
        select type (m)
        type is (kane_run_t)
            call evaluate(m%sys%p, y, m%th3, mo, stat, sink%parts)
            if (stat%code == 0 .and. .not. sink%parts%accelerations) then
                ! tensions for the model checks only, from the integrator's derivative
                if (k == 0) then
                    call m%sys%rhs(0.0_dp, y, ydot, stat)
                else
                    call m%solver%dense(t, 1, ydot, stat)
                end if
                if (stat%code == 0) call step_tensions(m%sys, y, ydot, mo%t_bc, mo%t_ad, stat)
            end if
            if (stat%code /= 0) then
                call append_tau(stat, t)
                return
            end if
            m%th3 = mo%th(3)
            call emit_row(sink%rb, t, k, mo, sink%e0, 'the motion left the range the model '// &
                          'covers', .true., sink%want, sink%sm, stat)
            if (stat%code /= 0) return
            if (sink%error_estimate .and. k > 0) then
                call cpu_time(t_e0)
                call sink%solver2%integrate(m%sys, t, y2, stat)
                if (stat%code /= 0) then
                    stat%msg = 'error estimate (rerun at rtol/100): '//stat%msg
                    return
                end if
                call add_estimate(sink%sm, angle_difference(y, y2), &
                                  abs(sway_of(m%sys%p, y) - sway_of(m%sys%p, y2)), t_e0)
            end if
        end select
    end subroutine kane_dat_take




    !> Open OUTDIR/NAME.dat (a file of the run, see output_io) and write its header: title,
    !! units, an optional model note, the effective deck, the line of the &output columns.
    subroutine open_dat(d, outdir, note, fs, u, sumpath, stat)
        type(deck_t), intent(in) :: d           !! the deck
        character(len=*), intent(in) :: outdir  !! output directory
        character(len=*), intent(in) :: note    !! extra '# ' line ('' for none)
        type(out_files_t), intent(inout) :: fs  !! the run's files
        integer, intent(out) :: u               !! the open unit
        character(len=:), allocatable, intent(out) :: sumpath   !! the summary's name
        type(status_t), intent(out) :: stat     !! ERR_IO
        integer :: ios
        sumpath = outdir//'/'//d%name//'.summary'
        call fs%open(outdir//'/'//d%name//'.dat', u, stat)
        if (stat%code /= 0) return
        write (u, '(a)', iostat=ios) '# bifilar: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# time tau = sqrt(g/b'') t; lengths over '// &
            'b''; tensions over m g; energy over m g b''; angles in rad'
        if (ios == 0 .and. len(note) > 0) write (u, '(a)', iostat=ios) note
        if (ios == 0) call deck_echo(d, u, ios)
        if (ios == 0) write (u, '(a)', iostat=ios) '# '//trim(d%output%columns)
        if (ios /= 0) call set_error(stat, ERR_IO, 'cannot write '//outdir//'/'//d%name// &
                                     '.dat (iostat '//sci(real(ios, dp), 0)//')')
    end subroutine open_dat

    !> Write one checked output row (the asked columns: tau as F14.6, the others as
    !! ES24.15E3, by fast_format: the run-time library's text) and fold it into the run's
    !! figures.
    subroutine record_row(rb, row, want, mo, sm, stat)
        type(row_block_t), intent(inout) :: rb  !! rows of the open .dat file
        real(dp), intent(in) :: row(NCOL)       !! tau, ..., energy_error, constraint_residual
        logical, intent(in) :: want(NCOL)       !! the columns written
        type(motion_t), intent(in) :: mo        !! the motion of the row
        type(run_summary_t), intent(inout) :: sm
        type(status_t), intent(out) :: stat     !! ERR_IO when the row cannot be written
        character(len=ROW_WIDTH) :: line
        integer :: j, n
        n = 0
        if (want(1)) then
            call f_field(row(1), 6, line(1:14))
            n = 14
        end if
        do j = 2, NCOL
            if (.not. want(j)) cycle
            call es_field(row(j), 15, line(n + 1:n + 24))
            n = n + 24
        end do
        if (rb%used + n + 1 > ROW_BLOCK) then
            call flush_rows(rb, stat)
            if (stat%code /= 0) return
        else
            stat%code = 0
        end if
        rb%text(rb%used + 1:rb%used + n) = line(1:n)
        rb%text(rb%used + n + 1:rb%used + n + 1) = achar(10)
        rb%used = rb%used + n + 1
        sm%rows = sm%rows + 1
        sm%tau_reached = row(1)
        sm%max_abs_theta1 = max(sm%max_abs_theta1, abs(mo%th(1)))
        sm%max_abs_theta4 = max(sm%max_abs_theta4, abs(mo%th(4)))
        sm%max_q = max(sm%max_q, mo%q_sway)
        sm%max_q_axis = max(sm%max_q_axis, mo%q_axis)
        sm%max_abs_energy_error = max(sm%max_abs_energy_error, abs(row(COL_ENERGY)))
        sm%max_abs_constraint_residual = max(sm%max_abs_constraint_residual, abs(mo%residual))
        sm%min_tension = min(sm%min_tension, mo%t_bc, mo%t_ad)
    end subroutine record_row

    !> Write the rows collected in rb (one WRITE; the last newline is the record's own).
    subroutine flush_rows(rb, stat)
        type(row_block_t), intent(inout) :: rb
        type(status_t), intent(out) :: stat     !! ERR_IO when the rows cannot be written
        integer :: ios
        character(len=200) :: msg
        stat%code = 0
        if (rb%used == 0) return
        write (rb%unit, '(a)', iostat=ios, iomsg=msg) rb%text(1:rb%used - 1)
        rb%used = 0
        if (ios /= 0) call set_error(stat, ERR_IO, 'cannot write rows of the .dat file: '// &
                                     trim(msg))
    end subroutine flush_rows

    !> The .dat columns a deck asks for (&output columns), as a mask over OUTPUT_COLUMNS.
    subroutine column_mask(d, want)
        type(deck_t), intent(in) :: d           !! the deck
        logical, intent(out) :: want(NCOL)
        integer :: j, i1, i2
        i1 = 1
        do j = 1, NCOL
            i2 = index(OUTPUT_COLUMNS(i1:)//' ', ' ') + i1 - 2     ! the j-th name: i1:i2
            want(j) = index(' '//trim(d%output%columns)//' ', ' '//OUTPUT_COLUMNS(i1:i2)//' ') > 0
            i1 = i2 + 2
        end do
    end subroutine column_mask

    !> Append " at tau = TAU" (f0.4) to a failure's message.
    subroutine append_tau(stat, tau)
        type(status_t), intent(inout) :: stat
        real(dp), intent(in) :: tau
        stat%msg = stat%msg//' at tau = '//fixed(tau, 6)
    end subroutine append_tau

    !> One output row from the motion at tau (row k; the energy error is against the energy
    !! of row 0, kept in e0): refused (ERR_NUMERIC, `why` in the message) when not finite,
    !! then the paper model's checks when asked (model_checks), then written (record_row).
    subroutine emit_row(rb, tau, k, mo, e0, why, paper_checks, want, sm, stat)
        type(row_block_t), intent(inout) :: rb  !! rows of the open .dat file
        real(dp), intent(in) :: tau             !! time of the row
        integer, intent(in) :: k                !! row number (0: the start)
        type(motion_t), intent(in) :: mo        !! the motion at tau
        real(dp), intent(inout) :: e0           !! energy at the start (set at k = 0)
        character(len=*), intent(in) :: why     !! what a non-finite row means for the model
        logical, intent(in) :: paper_checks     !! apply model_checks (the paper's model)
        logical, intent(in) :: want(NCOL)       !! the columns written
        type(run_summary_t), intent(inout) :: sm
        type(status_t), intent(out) :: stat
        real(dp) :: row(NCOL)
        stat%code = 0
        if (k == 0) e0 = mo%energy
        row = [tau, mo%th, mo%thd, mo%q_sway, mo%q_axis, mo%t_bc, mo%t_ad, &
               mo%energy - e0, mo%residual]
        if (.not. all_finite(row)) then
            call set_error(stat, ERR_NUMERIC, 'non-finite result at tau = '//fixed(tau, 6)// &
                           ': '//why)
            return
        end if
        if (paper_checks) then
            call model_checks(mo, tau, stat)
            if (stat%code /= 0) return
        end if
        call record_row(rb, row, want, mo, sm, stat)
    end subroutine emit_row

    !> Add one row's differences from the error-estimate rerun (angles, Q) and the CPU time
    !! since t_e0 (cpu_time) to the summary.
    subroutine add_estimate(sm, dtheta, dq, t_e0)
        type(run_summary_t), intent(inout) :: sm
        real(dp), intent(in) :: dtheta, dq      !! differences at this row (rad, b')
        real(dp), intent(in) :: t_e0            !! cpu_time before the rerun's step
        real(dp) :: t_e1
        sm%error_estimate_theta = max(sm%error_estimate_theta, dtheta)
        sm%error_estimate_q = max(sm%error_estimate_q, dq)
        call cpu_time(t_e1)
        sm%error_estimate_cpu = sm%error_estimate_cpu + (t_e1 - t_e0)
    end subroutine add_estimate

    !> End a run: the solver's figures and the CPU time into sm; the .dat closed and checked
    !! (it waits in fs for the commit) unless stat carries an error.
    subroutine finish_run(st, t_cpu0, fs, u, sm, stat)
        type(integrator_stats_t), intent(in) :: st  !! the main solver's statistics
        real(dp), intent(in) :: t_cpu0          !! cpu_time at the start of the integration
        type(out_files_t), intent(inout) :: fs  !! the run's files
        integer, intent(in) :: u                !! the open .dat unit
        type(run_summary_t), intent(inout) :: sm
        type(status_t), intent(inout) :: stat   !! the run's status; ERR_IO from the close
        real(dp) :: t_cpu1
        call cpu_time(t_cpu1)
        sm%cpu_seconds = t_cpu1 - t_cpu0 - sm%error_estimate_cpu
        sm%steps = st%steps
        sm%rhs_evaluations = st%rhs_evals
        sm%jacobian_evaluations = st%jac_evals
        sm%method_switches = st%method_switches
        if (stat%code /= 0) return
        call fs%close(u, 0, stat)
    end subroutine finish_run

    !> Write OUTDIR/NAME.summary (key = value lines) of a finished run.
    subroutine write_summary(d, sm, fs, sumpath, stat)
        type(deck_t), intent(in) :: d           !! the deck
        type(run_summary_t), intent(in) :: sm   !! figures of the run
        type(out_files_t), intent(inout) :: fs  !! the run's files
        character(len=*), intent(in) :: sumpath !! summary file
        type(status_t), intent(out) :: stat     !! ERR_IO
        integer :: u, ios
        call fs%open(sumpath, u, stat)
        if (stat%code /= 0) return
        write (u, '(a)', iostat=ios) '# bifilar summary: '//trim(d%scene%title)
        call write_kv(u, 'deck', d%path, ios)
        call write_kv(u, 'cpu_seconds', sm%cpu_seconds, ios)
        call write_kv(u, 'steps', sm%steps, ios)
        call write_kv(u, 'rhs_evaluations', sm%rhs_evaluations, ios)
        call write_kv(u, 'jacobian_evaluations', sm%jacobian_evaluations, ios)
        call write_kv(u, 'method_switches', sm%method_switches, ios)
        call write_kv(u, 'rows', sm%rows, ios)
        call write_kv(u, 'tau_end', sm%tau_reached, ios)
        call write_kv(u, 'max_abs_theta1', sm%max_abs_theta1, ios)
        call write_kv(u, 'max_abs_theta4', sm%max_abs_theta4, ios)
        if (sm%have_sway) then
            call write_kv(u, 'max_Q', sm%max_q, ios)
            call write_kv(u, 'max_Q_axis', sm%max_q_axis, ios)
        end if
        if (sm%have_energy) call write_kv(u, 'max_abs_energy_error', sm%max_abs_energy_error, &
                                          ios)
        if (sm%have_residual) call write_kv(u, 'max_abs_constraint_residual', &
                                            sm%max_abs_constraint_residual, ios)
        call write_kv(u, 'min_tension', sm%min_tension, ios)
        call write_kv(u, 'method', trim(sm%method), ios)
        if (d%integration%error_estimate) then
            call write_kv(u, 'error_estimate_rtol', sm%error_estimate_rtol, ios)
            call write_kv(u, 'error_estimate_theta', sm%error_estimate_theta, ios)
            call write_kv(u, 'error_estimate_Q', sm%error_estimate_q, ios)
        end if
        if (sm%elastic) then
            call write_kv(u, 'slack_time_BC', sm%slack_time(1), ios)
            call write_kv(u, 'slack_time_AD', sm%slack_time(2), ios)
            call write_kv(u, 'slack_intervals_BC', sm%slack_intervals(1), ios)
            call write_kv(u, 'slack_intervals_AD', sm%slack_intervals(2), ios)
            call write_kv(u, 'cable_switches', sm%cable_switches, ios)
        end if
        call fs%close(u, ios, stat)
    end subroutine write_summary

    !> Write OUTDIR/NAME.slack: one line per slack interval of a cable (model = 'elastic'),
    !! in the order they began; an interval still open at the end of the run ends at tau_end
    !! and is marked open = 1.
    subroutine write_slack_list(d, outdir, fs, list, tau_end, stat)
        type(deck_t), intent(in) :: d           !! the deck
        character(len=*), intent(in) :: outdir  !! output directory
        type(out_files_t), intent(inout) :: fs  !! the run's files
        type(slack_interval_t), intent(in) :: list(:)  !! elastic_solver_t%slack_list()
        real(dp), intent(in) :: tau_end         !! tau reached by the run
        type(status_t), intent(out) :: stat     !! ERR_IO
        character(len=:), allocatable :: path
        real(dp) :: t1
        integer :: u, i, ios
        path = outdir//'/'//d%name//'.slack'
        call fs%open(path, u, stat)
        if (stat%code /= 0) return
        write (u, '(a)', iostat=ios) '# bifilar slack intervals: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# cable (1 = BC, 2 = AD), tau_start, '// &
            'tau_end, duration, open (1: still slack at the end of the run)'
        do i = 1, size(list)
            t1 = list(i)%tau_end
            if (list(i)%open) t1 = tau_end
            if (ios == 0) write (u, '(i2,3es24.15e3,i3)', iostat=ios) list(i)%cable, &
                list(i)%tau_start, t1, t1 - list(i)%tau_start, merge(1, 0, list(i)%open)
        end do
        call fs%close(u, ios, stat)
    end subroutine write_slack_list

    !> run_simulation for &scene model = 'elastic': the elastic-cable model (elastic_model)
    !! from the same start (start_state, then elastic_start: the paper's pose, velocities
    !! and tensions), per-state absolute tolerances from elastic_atol, the same rows and
    !! columns (theta from the body's pose, T_BC and T_AD from the springs, energy including
    !! the springs', constraint_residual = |AD| - l' over b').  A slack cable is a state of
    !! this model, not an error: the integration (elastic_solver) locates each switch
    !! between taut and slack to roundoff in tau, the summary gives each cable's slack time
    !! and number of slack intervals, and OUTDIR/NAME.slack lists the intervals.  The run
    !! stops with ERR_MODEL when a cable stretches beyond STRAIN_MAX, and with ERR_NUMERIC
    !! when the cables chatter between taut and slack (elastic_solver: the tolerance does
    !! not resolve the stretch) or the integrator fails.
    subroutine run_elastic(d, outdir, fs, sm, stat)
        type(deck_t), intent(in) :: d           !! the deck (model = 'elastic')
        character(len=*), intent(in) :: outdir  !! output directory
        type(out_files_t), intent(inout) :: fs  !! the run's files
        type(run_summary_t), intent(out) :: sm  !! figures of the run
        type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL or ERR_IO
        type(elastic_run_t) :: m
        type(elastic_dat_sink_t) :: sink
        type(pace_t) :: pace
        type(motion_t) :: mo
        type(elastic_cables_t) :: cab
        real(dp) :: yc(NSTATE), th0(5), y(ELASTIC_NSTATE), atol(ELASTIC_NSTATE)
        real(dp) :: t_cpu0, rt2
        real(dp), allocatable :: times(:)
        character(len=:), allocatable :: sumpath
        integer :: u

        sink%sm%elastic = .true.
        call column_mask(d, sink%want)
        call make_pendulum(rig_of(d), m%sys%p, stat)
        if (stat%code /= 0) return
        call start_state(start_of(d), m%sys%p, yc, th0, stat)
        if (stat%code /= 0) return
        m%sys%stiffness = d%cables%stiffness
        m%sys%damping = d%cables%damping
        call elastic_start(m%sys, yc, y, stat)
        if (stat%code /= 0) then
            stat%msg = 'elastic start: '//stat%msg
            return
        end if
        atol = elastic_atol(m%sys, d%integration%atol, d%integration%rtol)

        call open_dat(d, outdir, '# model elastic: T_BC, T_AD from the springs (0 when '// &
            'slack); energy_error includes the springs'' energy; constraint_residual = '// &
            '|AD| - l''', fs, u, sumpath, stat)
        if (stat%code /= 0) return
        sink%rb%unit = u

        call cpu_time(t_cpu0)
        sink%sm%method = merge('radau', 'lsoda', method_of(d) == SOLVER_RADAU)
        call m%solver%init(m%sys, 0.0_dp, y, d%integration%rtol, atol, stat, &
                           tcrit=d%integration%tau_end, method=method_of(d))
        if (stat%code /= 0) return
        if (d%integration%error_estimate) then
            rt2 = tighter_rtol(d%integration%rtol)
            sink%sys2 = m%sys                    ! its own cable modes
            call sink%solver2%init(sink%sys2, 0.0_dp, y, rt2, elastic_atol(sink%sys2, &
                                   d%integration%atol*rt2/d%integration%rtol, rt2), stat, &
                                   tcrit=d%integration%tau_end, method=method_of(d))
            if (stat%code /= 0) return
            sink%error_estimate = .true.
            sink%sm%error_estimate_rtol = rt2
            sink%sm%error_estimate_theta = 0.0_dp
            sink%sm%error_estimate_q = 0.0_dp
        end if
        m%y0 = y
        m%ystep = y
        m%t_end = d%integration%tau_end
        m%remedy = 'raise rtol/atol, shorten tau_end, or add &cables damping'
        sink%th_row = th0
        m%th_step = th0
        call elastic_evaluate(m%sys, y, th0(3), mo, stat, th0, cab)
        if (stat%code /= 0) return
        call output_times(d, times)
        call pace%start('bifilar: note: '//d%path//': simulate (elastic cables, stiffness '// &
                        sci(d%cables%stiffness, 2)//')', 0.0_dp, d%integration%tau_end, 'tau')
        call drive(m, times, sink, stat, pace)
        sm = sink%sm
        sm%slack_time = m%solver%slack_time()
        sm%slack_intervals = m%solver%slack_intervals()
        sm%cable_switches = m%solver%switches()
        if (stat%code == 0) call flush_rows(sink%rb, stat)
        call finish_run(m%solver%stats(), t_cpu0, fs, u, sm, stat)
        if (stat%code /= 0) return
        call write_slack_list(d, outdir, fs, m%solver%slack_list(), sm%tau_reached, stat)
        if (stat%code /= 0) return
        call write_summary(d, sm, fs, sumpath, stat)
    end subroutine run_elastic

    !> One row of the elastic model's .dat file (the paper's angles from the body's pose,
    !! tensions from the springs), and the error-estimate rerun brought to tau.
    subroutine elastic_dat_take(sink, m, k, t, y, stat)
        class(elastic_dat_sink_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k                !! row number (0: the start)
        real(dp), intent(in) :: t               !! tau of the row
        real(dp), intent(in) :: y(:)            !! state there
        type(status_t), intent(out) :: stat
        type(motion_t) :: mo, mo2
        type(status_t) :: s2
        real(dp) :: y2(ELASTIC_NSTATE), t_e0
        stat%code = 0
        select type (m)
        type is (elastic_run_t)
            call elastic_evaluate(m%sys, y, sink%th_row(3), mo, stat, sink%th_row)
            if (stat%code /= 0) then
                call append_tau(stat, t)
                return
            end if
            sink%th_row = mo%th
            call emit_row(sink%rb, t, k, mo, sink%e0, 'the body''s pose left the range the '// &
                          'paper''s angles cover (line CD vertical?)', .false., sink%want, &
                          sink%sm, stat)
            if (stat%code /= 0) return
            if (sink%error_estimate .and. k > 0) then
                call cpu_time(t_e0)
                call sink%solver2%integrate(sink%sys2, t, y2, stat)
                if (stat%code /= 0) then
                    stat%msg = 'error estimate (rerun at rtol/100): '//stat%msg
                    return
                end if
                call elastic_evaluate(sink%sys2, y2, mo%th(3), mo2, s2, mo%th)
                if (s2%code == 0) then
                    call add_estimate(sink%sm, maxval(abs(mo%th([1, 4, 5]) - &
                                      mo2%th([1, 4, 5]))), abs(mo%q_sway - mo2%q_sway), t_e0)
                else
                    call add_estimate(sink%sm, 0.0_dp, 0.0_dp, t_e0)
                end if
            end if
        end select
    end subroutine elastic_dat_take











end submodule simulate_impl
