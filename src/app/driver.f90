!> One deck from start to end, as the program runs it: read and validate the deck, check
!! the preconditions of every analysis it asks for before any computing, run the analyses
!! with all their files in one out_files_t, and commit those files together at the end, or
!! remove every one of them when anything fails.  The main program only reads the command
!! line, calls run_deck for each deck and prints what comes back.
!!
!! Signals: the line a signal prints names the deck and the analysis running (module
!! signals); the deck's files are renamed into place with signals deferred, so that a signal
!! never leaves part of a set (the main program acts on it once the deck's line is out).
!!
!! In an MPI run (bin/bifilar_mpi) rank 0 runs the decks; the other ranks only compute
!! points of sweeps (serve_sweeps): for each sweep rank 0 announces, they read the deck,
!! build the same task and take part (module sweep_engine).
module driver
    use, intrinsic :: iso_fortran_env, only: error_unit
    use kinds, only: dp
    use status, only: status_t, STATUS_OK, ERR_DECK, exit_status_of, status_meaning
    use text, only: itoa, sci, fixed, quoted
    use deck, only: deck_t, read_deck, read_deck_text, analysis_requested
    use output_io, only: out_files_t, remove_file, path_fits
    use signals, only: signals_deck, signals_stage, signals_defer
    use simulate, only: run_simulation, run_summary_t, simulation_ready
    use rig, only: rig_of, make_pendulum
    use stability, only: run_floquet, run_chart, floquet_ready, chart_task, chart_task_t
    use sweep_engine, only: sweep_options_t, sweep_report_t, sweep_job_t, sweep_task_t, &
        sweep_next_job, sweep_serve, checkpoint_path
    use floquet, only: floquet_result_t
    use work_precision, only: run_work_precision, wp_result_t
    use design, only: run_design, design_ready, design_result_t, design_task, DESIGN_STAGES
    use identify, only: identify_ready, run_identify, identify_result_t, identify_mc_task, &
        warning_t, identify_input_t
    use tensor, only: tensor_ready, run_tensor, tensor_result_t, tensor_sweep_task
    use monte_carlo, only: MC_ANALYSIS, MC_TENSOR
    use geometry, only: pendulum_t
    implicit none
    private

    public :: run_deck, exit_status, error_line, serve_sweeps

    !> The program's version (bifilar --version).
    character(len=*), parameter, public :: BIFILAR_VERSION = '1.1'

    !> The longest file name a deck NAME makes in the output folder is NAME followed by
    !! this (a design's last checkpoint), before the temporary suffix.
    character(len=*), parameter :: LONGEST_EXT = '.design_precision.partial'

    !> The files an analysis may write, NAME followed by one of these: when a deck's run
    !! commits its files, those of its analyses that this run did not write are removed
    !! (an old NAME.fit.dat of a record beside a new NAME.identify from periods).
    type :: owned_t
        character(len=16) :: analysis
        character(len=16) :: ext
    end type owned_t
    type(owned_t), parameter :: OWNED(*) = [ &
        owned_t('simulate', '.dat'), owned_t('simulate', '.summary'), &
        owned_t('simulate', '.slack'), owned_t('floquet', '.floquet'), &
        owned_t('chart', '.chart.dat'), owned_t('work_precision', '.wp.dat'), &
        owned_t('work_precision', '.wp_rk4.dat'), owned_t('work_precision', '.wp_radau.dat'), &
        owned_t('design', '.design'), owned_t('identify', '.identify'), &
        owned_t('identify', '.fit.dat'), owned_t('identify', '.periods.dat'), &
        owned_t('tensor', '.tensor'), owned_t('tensor', '.tensor.dat'), &
        owned_t('tensor', '.plan.csv')]

contains

    !> Run the deck at `path` into the folder `outdir` (which exists).  On success `line`
    !! is the deck's one summary line and stat is OK; on failure stat carries the error
    !! (its message without the deck's name: error_line adds it) and no file of the run is
    !! left in outdir.  The sweeps (chart, design) run first, before any file of the run is
    !! staged (the chart's before the design's); identify's Monte Carlo is a sweep too, in its
    !! turn.  Their checkpoints (OUTDIR/NAME.chart.partial, NAME.design*.partial,
    !! NAME.identify_mc.partial) are removed once the run's files are committed, and kept
    !! when the run fails after them (--resume reuses them).  On a commit the files of the
    !! deck's analyses that this run did not write are removed (OWNED).
    !! Warnings (a suspicious result that stands, a checkpoint that could not be written:
    !! one line each) go to stderr as "bifilar: warning: DECK: ...", or to `warnings` when
    !! given; they come once the deck's files are committed.
    !! With signals deferred when it returns (module signals): the caller prints the deck's
    !! line, then releases them.
    subroutine run_deck(path, outdir, line, stat, options, warnings)
        character(len=*), intent(in) :: path        !! deck file
        character(len=*), intent(in) :: outdir      !! output folder
        character(len=:), allocatable, intent(out) :: line   !! summary (on success)
        type(status_t), intent(out) :: stat         !! the first failure
        type(sweep_options_t), intent(in), optional :: options   !! --resume, --checkpoint
        !> the run's warnings, returned instead of written to stderr
        type(warning_t), allocatable, intent(out), optional :: warnings(:)
        type(deck_t) :: d
        type(sweep_report_t) :: rep
        character(len=:), allocatable :: chart_part, design_part
        type(out_files_t) :: files
        type(run_summary_t) :: sm
        type(floquet_result_t) :: fr
        type(wp_result_t) :: wp
        type(design_result_t) :: dr
        type(identify_result_t) :: idr
        type(tensor_result_t) :: tsr
        type(warning_t), allocatable :: ws(:)
        type(identify_input_t) :: idin              !! what identify_ready read, read once
        integer :: nstable, nfailed, k
        real(dp) :: secs

        line = ''
        allocate (ws(0))
        call signals_deck(path)
        call read_deck(path, d, stat)
        if (stat%code /= STATUS_OK) return
        ! the output folder can take the deck's files (before any computing)
        call path_fits(outdir, d%name//LONGEST_EXT, stat)
        if (stat%code /= STATUS_OK) return

        ! every analysis's preconditions before any computing
        if (analysis_requested(d, 'simulate') .or. analysis_requested(d, 'work_precision')) &
            call simulation_ready(d, stat)
        if (stat%code == STATUS_OK .and. analysis_requested(d, 'floquet')) &
            call floquet_ready(d, stat)
        if (stat%code == STATUS_OK .and. analysis_requested(d, 'chart')) &
            call chart_ready(d, stat)
        if (stat%code == STATUS_OK .and. analysis_requested(d, 'design')) &
            call design_ready(d, stat)
        if (stat%code == STATUS_OK .and. (analysis_requested(d, 'floquet') .or. &
            analysis_requested(d, 'chart') .or. analysis_requested(d, 'design'))) &
            call undamped_ready(d, stat)
        if (stat%code == STATUS_OK .and. analysis_requested(d, 'identify')) &
            call identify_ready(d, stat, idin)
        if (stat%code == STATUS_OK .and. analysis_requested(d, 'tensor')) &
            call tensor_ready(d, stat)
        if (stat%code /= STATUS_OK) return

        line = d%name//':'
        chart_part = ''
        design_part = ''
        run: block
            if (analysis_requested(d, 'chart')) then
                call signals_stage('chart')
                call run_chart(d, outdir, nstable, secs, stat, files=files, nfailed=nfailed, &
                               options=options, report=rep)
                call add_warning(rep)
                if (stat%code /= STATUS_OK) exit run
                chart_part = ' chart '//itoa(d%chart%nx*d%chart%ny)//' points, '// &
                    itoa(nstable)//' stable, '//fixed(secs, 2)//' s'//ranks_note(rep)
                if (nfailed > 0) chart_part = chart_part//', '//itoa(nfailed)// &
                    ' failed (-2 in the file)'
                chart_part = chart_part//resume_note(rep)//';'
            end if
            if (analysis_requested(d, 'design')) then
                call signals_stage('design')
                call run_design(d, outdir, dr, stat, files=files, options=options, report=rep)
                call add_warning(rep)
                if (stat%code /= STATUS_OK) exit run
                design_part = ' design '//itoa(size(dr%ls)*size(dr%bs))//' candidates x '// &
                    itoa(size(dr%amps))//' amplitudes, '//itoa(dr%n_stable)//' stable, '// &
                    'recommended l = '//sci(dr%ls(dr%il), 4)//', b = '//sci(dr%bs(dr%ib), 4)// &
                    ', b_prime = '//sci(dr%bps(dr%ib), 4)// &
                    ', u(I1)/I1 = '//sci(dr%u_rel(dr%il, dr%ib), 2)//', '// &
                    fixed(dr%wall_seconds, 2)//' s'//ranks_note(rep)
                if (dr%n_failed > 0) design_part = design_part//', '//itoa(dr%n_failed)// &
                    ' failed points'
                design_part = design_part//resume_note(rep)//';'
            end if
            if (analysis_requested(d, 'work_precision')) then
                call signals_stage('work_precision')
                call run_work_precision(d, outdir, wp, stat, quiet=.true., files=files)
                if (stat%code /= STATUS_OK) exit run
                line = line//' work_precision '//itoa(count(wp%lsoda%ok))//' LSODA, '
                if (trim(d%scene%model) == 'elastic') &
                    line = line//itoa(count(wp%radau%ok))//' Radau, '
                line = line//itoa(count(wp%rk4%ok))//' RK4 points, reference confirmed to '// &
                    sci(wp%ref_agreement_theta, 1)//' rad;'
            end if
            if (analysis_requested(d, 'floquet')) then
                call signals_stage('floquet')
                call run_floquet(d, outdir, fr, stat, files=files)
                if (stat%code /= STATUS_OK) exit run
                line = line//' floquet period '//fixed(fr%period, 6)//', max modulus '// &
                    sci(fr%max_modulus, 5)//', stable '//trim(merge('yes', 'no ', fr%stable))//';'
            end if
            line = line//chart_part//design_part
            if (analysis_requested(d, 'identify')) then
                call signals_stage('identify')
                call run_identify(d, outdir, idr, stat, files, options, rep, idin)
                call add_warning(rep)
                if (stat%code /= STATUS_OK) exit run
                if (idr%uncertainty_given) then
                    line = line//' identify I1 = '//sci(idr%i1, 5)//' ± '// &
                        sci(idr%u_i1_expanded, 2)//' (k = '//fixed(idr%k, 1)//', 95 %)'
                else
                    line = line//' identify I1 = '//sci(idr%i1, 5)//' (no uncertainty '// &
                        'given: every u_* of &measurement is 0)'
                end if
                do k = 2, idr%np
                    if (idr%names(k) == 'c_v' .or. idr%names(k) == 'c_q') line = line// &
                        ', '//trim(idr%names(k))//' = '//sci(idr%p(k), 3)//' ± '// &
                        sci(idr%k*idr%u_p(k), 2)
                end do
                if (idr%n_trials > 1) line = line//', '//itoa(idr%n_trials)//' releases '// &
                    trim(idr%consistency)
                line = line//', period model '//trim(idr%period_model)
                if (allocated(idin%recs)) then
                    ! a gyro export read without record_columns: the axis taken
                    if (size(idin%recs) > 0) then
                        if (idin%recs(1)%axis_chosen) line = line//', record axis '// &
                            quoted(trim(idin%recs(1)%value_name))//' (largest swing)'
                    end if
                end if
                if (idr%u_i1_mc >= 0.0_dp) then
                    line = line//' (Monte Carlo u '//sci(idr%u_i1_mc, 2)//' from '// &
                        itoa(d%measurement%monte_carlo)//' samples, '// &
                        fixed(rep%wall_seconds, 2)//' s'//ranks_note(rep)//resume_note(rep)//')'
                end if
                if (idr%i1_linear > 0.0_dp) then
                    line = line//', linear formula '//sci(idr%i1_linear, 5)//' ('// &
                        trim(merge('+', ' ', idr%linear_error >= 0.0_dp))// &
                        fixed(100.0_dp*idr%linear_error, 2)//' %)'
                else
                    line = line//', no period in the record for the linear formula'
                end if
                do k = 1, size(idr%warnings)
                    call add_text(idr%warnings(k)%s)
                end do
                line = line//', '//itoa(idr%iterations)//' iterations;'
            end if
            if (analysis_requested(d, 'tensor')) then
                call signals_stage('tensor')
                call run_tensor(d, outdir, tsr, stat, files, options, rep)
                call add_warning(rep)
                if (stat%code /= STATUS_OK) exit run
                line = line//tensor_summary(tsr, rep)
                if (allocated(tsr%warning)) then
                    if (len(tsr%warning) > 0) call add_text(tsr%warning)
                end if
            end if
            if (analysis_requested(d, 'simulate')) then
                call signals_stage('simulate')
                call run_simulation(d, outdir, sm, stat, files=files)
                if (stat%code /= STATUS_OK) exit run
                line = line//' simulate cpu '//fixed(sm%cpu_seconds, 4)//' s, steps '// &
                    itoa(sm%steps)//', rhs '//itoa(sm%rhs_evaluations)//', max |dE| '// &
                    sci(sm%max_abs_energy_error, 2)//', max |residual| '// &
                    sci(sm%max_abs_constraint_residual, 2)//';'
            end if
            ! renamed into place together, and the line printed, before a signal is acted on
            call signals_defer()
            call files%commit(stat, stale_files())  ! on failure it removes them all
            if (stat%code == STATUS_OK) then
                line = line(1:len(line) - 1)
                if (analysis_requested(d, 'chart')) &
                    call remove_file(checkpoint_path(outdir, d%name, 'chart'))
                if (analysis_requested(d, 'design')) then
                    do k = 1, size(DESIGN_STAGES)
                        call remove_file(checkpoint_path(outdir, d%name, trim(DESIGN_STAGES(k))))
                    end do
                end if
                if (analysis_requested(d, 'identify')) &
                    call remove_file(checkpoint_path(outdir, d%name, MC_ANALYSIS))
                if (analysis_requested(d, 'tensor')) &
                    call remove_file(checkpoint_path(outdir, d%name, MC_TENSOR))
                if (present(warnings)) then
                    warnings = ws
                else
                    do k = 1, size(ws)
                        call warn(path, ws(k)%s)
                    end do
                end if
            end if
            return
        end block run
        call files%discard()                    ! a failed analysis: remove every file

    contains

        !> A sweep's warning (a checkpoint that could not be written), for the end.
        subroutine add_warning(r)
            type(sweep_report_t), intent(in) :: r
            if (.not. allocated(r%warning)) return
            if (len(r%warning) > 0) call add_text(r%warning)
        end subroutine add_warning

        !> One more warning (grown by hand: gfortran 12 loses the text of a constructor
        !! [ws, warning_t(s)] here).
        subroutine add_text(s)
            character(len=*), intent(in) :: s
            type(warning_t), allocatable :: grown(:)
            integer :: j
            allocate (grown(size(ws) + 1))
            do j = 1, size(ws)
                call move_alloc(ws(j)%s, grown(j)%s)
            end do
            grown(size(ws) + 1)%s = s
            call move_alloc(grown, ws)
        end subroutine add_text

        !> OUTDIR/NAME.EXT of every file the deck's analyses may write (OWNED).
        function stale_files() result(p)
            character(len=len(outdir) + len(d%name) + 17), allocatable :: p(:)
            integer :: j
            allocate (p(0))
            do j = 1, size(OWNED)
                if (analysis_requested(d, trim(OWNED(j)%analysis))) &
                    p = [character(len=len(p)) :: p, outdir//'/'//d%name//trim(OWNED(j)%ext)]
            end do
        end function stale_files

    end subroutine run_deck

    !> A warning: one line on stderr naming the deck (the run goes on, exit 0).
    subroutine warn(deck_path, msg)
        character(len=*), intent(in) :: deck_path   !! the deck as given
        character(len=*), intent(in) :: msg         !! what is suspicious, what to check
        write (error_unit, '(a)') 'bifilar: warning: '//deck_path//': '//msg
        flush (error_unit)
    end subroutine warn

    !> The summary line's part of analysis tensor: the principal moments with their u, the
    !! chi-square, how far the projection solution lies, the Monte Carlo, the plan.
    function tensor_summary(res, rep) result(s)
        type(tensor_result_t), intent(in) :: res    !! what tensor found
        type(sweep_report_t), intent(in) :: rep     !! its Monte Carlo's sweep
        character(len=:), allocatable :: s
        s = ' tensor'
        if (res%fitted) then
            s = s//' I_principal = '//sci(res%moments(1), 5)//', '//sci(res%moments(2), 5)// &
                ', '//sci(res%moments(3), 5)//' (u '//sci(res%u_moments(1), 2)//', '// &
                sci(res%u_moments(2), 2)//', '//sci(res%u_moments(3), 2)//'), chi2 '// &
                fixed(res%chi2, 2)//'/dof '//itoa(res%dof)//', '//itoa(res%hangs)// &
                ' hangs, projection off by '//sci(res%projection_difference, 2)
            if (res%mc_samples > 0) s = s//', Monte Carlo u '//sci(res%u_moments_mc(1), 2)// &
                ', '//sci(res%u_moments_mc(2), 2)//', '//sci(res%u_moments_mc(3), 2)// &
                ' from '//itoa(res%mc_samples)//' samples, '//fixed(rep%wall_seconds, 2)// &
                ' s'//ranks_note(rep)//resume_note(rep)
        end if
        if (res%plan > 0) then
            if (res%fitted) s = s//','
            s = s//' a plan of '//itoa(res%plan)//' hangs in '//res%plan_file
        end if
        s = s//';'
    end function tensor_summary

    !> The other ranks of an MPI run: for each sweep rank 0 announces, read its deck, build
    !! its task and compute points, until rank 0 ends the program.
    subroutine serve_sweeps()
        type(sweep_job_t) :: job
        type(deck_t) :: d
        type(status_t) :: st
        class(sweep_task_t), allocatable :: task
        type(chart_task_t), allocatable :: chart
        logical :: quit
        do
            call sweep_next_job(job, quit)
            if (quit) return
            if (len(job%deck_text) > 0) then
                call read_deck_text(job%deck_path, job%deck_text, d, st)
            else
                call read_deck(job%deck_path, d, st)
            end if
            if (st%code == STATUS_OK) then
                select case (job%analysis)
                case ('chart')
                    allocate (chart)
                    call chart_task(d, chart, st)
                    call move_alloc(chart, task)
                case ('design', 'design_edges', 'design_precision')
                    call design_task(job%analysis, d, job%payload, task, st)
                case (MC_ANALYSIS)
                    call identify_mc_task(d, job%payload, task, st)
                case (MC_TENSOR)
                    call tensor_sweep_task(d, job%payload, task, st)
                case default
                    st%code = ERR_DECK
                    st%msg = 'no sweep named '//job%analysis//' in this executable'
                end select
            else
                st%msg = job%deck_path//': '//st%msg
            end if
            if (allocated(task) .and. st%code == STATUS_OK) then
                call sweep_serve(job, st, task)
            else
                call sweep_serve(job, st)
            end if
            if (allocated(task)) deallocate (task)
        end do
    end subroutine serve_sweeps

    !> The preconditions of analyses = 'floquet', 'chart' and 'design': no &damping (they
    !! analyse the periodic torsion of the undamped model; a damped torsion is not periodic).
    subroutine undamped_ready(d, stat)
        type(deck_t), intent(in) :: d               !! the deck
        type(status_t), intent(inout) :: stat       !! ERR_DECK
        if (d%damping%c_v == 0.0_dp .and. d%damping%c_q == 0.0_dp) return
        stat%code = ERR_DECK
        stat%msg = '&damping c_v = '//sci(d%damping%c_v)//', c_q = '//sci(d%damping%c_q)// &
            ': floquet, chart and design analyse the periodic torsion of the undamped model (a '// &
            'damped torsion is not periodic); allowed: c_v = c_q = 0 with floquet, chart or design'
    end subroutine undamped_ready

    !> ' on N ranks' for a sweep of an MPI run ('' on one rank).
    function ranks_note(rep) result(s)
        type(sweep_report_t), intent(in) :: rep     !! the sweep's report
        character(len=:), allocatable :: s
        s = ''
        if (rep%ranks > 1) s = ' on '//itoa(rep%ranks)//' ranks'
    end function ranks_note

    !> What a sweep took from its checkpoint, or why it could not (--resume).
    function resume_note(rep) result(s)
        type(sweep_report_t), intent(in) :: rep     !! the sweep's report
        character(len=:), allocatable :: s
        s = ''
        if (rep%resumed > 0) s = ', '//itoa(rep%resumed)//' resumed from the checkpoint'
        if (rep%rejected > 0) s = s//', '//itoa(rep%rejected)//' of its points damaged or '// &
            'out of range: computed again'
        if (allocated(rep%note)) then
            if (len(rep%note) > 0) s = s//', '//rep%note//': computed afresh'
        end if
    end function resume_note

    !> The preconditions of analyses = 'chart': the deck's own scene has a reachable
    !! geometry (each point of the grid is checked when it is computed).
    subroutine chart_ready(d, stat)
        type(deck_t), intent(in) :: d               !! the deck
        type(status_t), intent(out) :: stat         !! ERR_DECK
        type(pendulum_t) :: p
        call make_pendulum(rig_of(d%suspension, d%body, d%damping, d%cables), p, stat)
        if (stat%code /= STATUS_OK) stat%msg = 'analyses = ''chart'': '//stat%msg
    end subroutine chart_ready

    !> The exit status for a status code (status's STATUS_TABLE): 2 bad deck, 3 numerical
    !! failure, 4 the model no longer holds, 5 output cannot be written.
    pure integer function exit_status(code)
        integer, intent(in) :: code                 !! status_t%code
        exit_status = exit_status_of(code)
    end function exit_status

    !> The one line printed for a failed deck: 'bifilar: error (KIND): DECK: MESSAGE', line
    !! breaks in the message turned into blanks.
    function error_line(deck_path, stat) result(s)
        character(len=*), intent(in) :: deck_path   !! the deck as given ('' for none)
        type(status_t), intent(in) :: stat          !! the failure
        character(len=:), allocatable :: s
        character(len=:), allocatable :: kind, msg
        integer :: i
        kind = status_meaning(stat%code)
        msg = '(no message)'
        if (allocated(stat%msg)) msg = stat%msg
        do i = 1, len(msg)
            if (iachar(msg(i:i)) < 32) msg(i:i) = ' '
        end do
        s = 'bifilar: error ('//kind//'): '
        if (len(deck_path) > 0) s = s//deck_path//': '
        s = s//msg
    end function error_line

end module driver
