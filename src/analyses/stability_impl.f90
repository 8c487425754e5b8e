!> The implementation of the stability analyses (submodule of stability): a Floquet
!! analysis of one scene and the chart of a grid, with their files.
submodule (stability) stability_impl
    use kinds, only: dp, deg
    use status, only: status_t, set_error, ERR_NUMERIC, ERR_DECK, ERR_MODEL, LSODA_ERR_MAX_STEPS
    use geometry, only: pendulum_t
    use deck, only: deck_t, deck_echo
    use rig, only: make_pendulum
    use deck_runs, only: rig_of, method_of, undamped_ready
    use integrators, only: sensitivities_for
    use floquet, only: floquet_result_t, floquet_analysis, check_torsion_scene, floquet_point, &
                       CHART_FAILED, point_values_valid, &
                       FLOQUET_MAX_STEPS
    use output_io, only: out_files_t, write_kv
    use sweep_engine, only: sweep_task_t, sweep_run, sweep_options_t, sweep_report_t, &
        checkpoint_path
    use text, only: itoa, sci, fixed
    use unused_arg, only: unused
    use analysis_base, only: ranks_note, resume_note
    implicit none

contains

    !> The preconditions of floquet: floquet_ready, and no &damping (undamped_ready).
    module procedure floquet_analysis_ready
        call unused(self)
        call floquet_ready(d, stat)
        if (stat%code == 0) call undamped_ready(d, stat)
    end procedure floquet_analysis_ready

    !> The run (run_floquet into the run's files).
    module procedure floquet_analysis_run
        call unused(options)
        call run_floquet(d, outdir, self%res, stat, files=files)
    end procedure floquet_analysis_run

    !> ' floquet period P, max modulus M, stable yes|no;'
    module procedure floquet_summary
        call unused(d)
        s = ' floquet period '//fixed(self%res%period, 6)//', max modulus '// &
            sci(self%res%max_modulus, 5)//', stable '// &
            trim(merge('yes', 'no ', self%res%stable))//';'
    end procedure floquet_summary

    !> The preconditions of chart: the deck's own scene has a reachable geometry (each
    !! point of the grid is checked when it is computed), and no &damping.
    module procedure chart_analysis_ready
        type(pendulum_t) :: p
        call unused(self)
        call make_pendulum(rig_of(d), p, stat)
        if (stat%code /= 0) then
            stat%msg = 'analyses = ''chart'': '//stat%msg
            return
        end if
        call undamped_ready(d, stat)
    end procedure chart_analysis_ready

    !> The run (run_chart into the run's files; its sweep's warning kept).
    module procedure chart_analysis_run
        call run_chart(d, outdir, self%nstable, self%wall_seconds, stat, files=files, &
                       nfailed=self%nfailed, options=options, report=self%rep)
        call self%add_report_warning(self%rep)
    end procedure chart_analysis_run

    !> ' chart N points, N stable, T s[ on N ranks][, N failed (-2 in the file)][resume];'
    module procedure chart_summary
        s = ' chart '//itoa(d%chart%nx*d%chart%ny)//' points, '//itoa(self%nstable)// &
            ' stable, '//fixed(self%wall_seconds, 2)//' s'//ranks_note(self%rep)
        if (self%nfailed > 0) s = s//', '//itoa(self%nfailed)//' failed (-2 in the file)'
        s = s//resume_note(self%rep)//';'
    end procedure chart_summary

    !> The task of sweep 'chart' on the other ranks of an MPI run (chart_task).
    module procedure chart_sweep_task
        type(chart_task_t), allocatable :: chart
        call unused(self)
        call unused(sweep)
        call unused(payload)
        allocate (chart)
        call chart_task(d, chart, stat)
        call move_alloc(chart, task)
    end procedure chart_sweep_task

    !> The preconditions of analyses = 'floquet', checked before any computing: the cables
    !! can reach and pure torsion is an exact motion of the scene (ERR_DECK otherwise).
    module procedure floquet_ready
        type(pendulum_t) :: p
        integer :: ivert
        call make_pendulum(rig_of(d), p, stat)
        if (stat%code /= 0) return
        call check_torsion_scene(p, ivert, stat)
        if (stat%code /= 0) stat%msg = 'analyses = ''floquet'' needs a scene in which pure '// &
            'torsion is an exact motion: '//stat%msg
    end procedure floquet_ready

    !> Floquet analysis of a deck at &floquet amplitude: OUTDIR/NAME.floquet.  With `files`
    !! the file joins the run's others (see run_simulation); without it it is committed at
    !! once.
    module procedure run_floquet
        type(out_files_t), target :: own
        type(out_files_t), pointer :: fs
        type(pendulum_t) :: p
        real(dp) :: t0, t1
        integer :: u, k, ios
        character(len=:), allocatable :: path
        fs => own
        if (present(files)) fs => files
        call floquet_ready(d, stat)
        if (stat%code /= 0) return
        call make_pendulum(rig_of(d), p, stat)
        if (stat%code /= 0) return
        call cpu_time(t0)
        call floquet_analysis(p, d%floquet%amplitude*deg, d%floquet%rtol, d%floquet%segments, &
                              res, stat, method_of(d), &
                              sensitivities_for(d%integration%sensitivities))
        call cpu_time(t1)
        if (stat%code /= 0) then
            call explain_budget(stat)
            stat%msg = 'floquet: '//stat%msg
            return
        end if
        path = outdir//'/'//d%name//'.floquet'
        call fs%open(path, u, stat)
        if (stat%code /= 0) return
        write (u, '(a)', iostat=ios) '# bifilar Floquet analysis of pure torsion: '// &
            trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# period in units of tau = sqrt(g/b'') t; '// &
            'multipliers of the monodromy matrix H(t*) of eq. (51)'
        call deck_echo(d, u, ios)
        call write_kv(u, 'period', res%period, ios)
        call write_kv(u, 'max_modulus', res%max_modulus, ios)
        call write_kv(u, 'stable', res%stable, ios)
        call write_kv(u, 'amplitude_deg', d%floquet%amplitude, ios)
        call write_kv(u, 'segments', d%floquet%segments, ios)
        call write_kv(u, 'rtol', d%floquet%rtol, ios)
        call write_kv(u, 'orbit_closure', res%orbit_closure, ios)
        call write_kv(u, 'trivial_residual', res%trivial_residual, ios)
        call write_kv(u, 'cpu_seconds', t1 - t0, ios)
        call write_kv(u, 'steps', res%steps, ios)
        call write_kv(u, 'rhs_evaluations', res%rhs_evaluations, ios)
        if (ios == 0) write (u, '(a)', iostat=ios) '# multipliers: re im modulus trivial '// &
            '(trivial: 1 by structure -- time shift, energy, constraint and its rate)'
        do k = 1, size(res%multipliers)
            if (ios == 0) write (u, '(3es24.15e3,2x,a)', iostat=ios) real(res%multipliers(k)), &
                aimag(res%multipliers(k)), abs(res%multipliers(k)), &
                merge('yes', 'no ', res%trivial(k))
        end do
        call fs%close(u, ios, stat)
        if (present(files)) return
        if (stat%code == 0) call own%commit(stat)
        if (stat%code /= 0) call own%discard()
    end procedure run_floquet

    !> A Floquet failure for want of steps gets its cause and remedy in the message.
    subroutine explain_budget(stat)
        type(status_t), intent(inout) :: stat   !! the failure
        if (stat%code /= LSODA_ERR_MAX_STEPS) return
        call set_error(stat, ERR_NUMERIC, 'the variational equations took more than '// &
            itoa(FLOQUET_MAX_STEPS)//' integrator steps over one segment of the half period '// &
            '(a body turning fast about a principal axis of small inertia?); raise &floquet '// &
            'rtol (e.g. 1e-8) or add segments')
    end subroutine explain_budget

    !> Set one chart variable (deck units: l and b over b', amplitude in degrees, r over b',
    !! lambda in radians, inertia_ratio = I3/I1) in p, or the amplitude.
    module procedure set_chart_variable
        select case (trim(name))
        case ('l')
            p%big_l = value
            p%big_lp = value
        case ('b')
            p%big_b = value
        case ('amplitude')
            amp_deg = value
        case ('r')
            p%r = value
        case ('lambda')
            p%lambda = value
        case ('inertia_ratio')
            p%inertia(3) = value*p%inertia(1)
        end select
    end procedure set_chart_variable

    !> The chart of a deck as a sweep (also built by the other ranks of an MPI run from the
    !! same deck): the scene, the swept variables and their grids.
    module procedure chart_task
        integer :: i, j
        call make_pendulum(rig_of(d), task%p0, stat)
        if (stat%code /= 0) return
        allocate (task%xs(d%chart%nx), task%ys(d%chart%ny))
        do i = 1, d%chart%nx
            task%xs(i) = d%chart%x_min + (d%chart%x_max - d%chart%x_min)*(i - 1)/(d%chart%nx - 1)
        end do
        do j = 1, d%chart%ny
            task%ys(j) = d%chart%y_min + (d%chart%y_max - d%chart%y_min)*(j - 1)/(d%chart%ny - 1)
        end do
        task%x = trim(d%chart%x)
        task%y = trim(d%chart%y)
        task%amplitude = d%floquet%amplitude
        task%rtol = d%floquet%rtol
        task%segments = d%floquet%segments
        task%method = method_of(d)
        task%sensitivities = sensitivities_for(d%integration%sensitivities)
    end procedure chart_task

    !> Chart point k: values = [max_modulus, period] (sentinels, see floquet_point).  Never
    !! fails itself.
    module procedure chart_point
        type(pendulum_t) :: p
        real(dp) :: amp
        integer :: ix, iy
        stat%code = 0
        ix = mod(i - 1, size(self%xs)) + 1
        iy = (i - 1)/size(self%xs) + 1
        p = self%p0
        amp = self%amplitude
        call set_chart_variable(self%x, self%xs(ix), p, amp)
        call set_chart_variable(self%y, self%ys(iy), p, amp)
        call floquet_point(p, amp, self%rtol, self%segments, values(1), values(2), self%method, &
                           self%sensitivities)
    end procedure chart_point

    !> Chart point i's values as read back from a checkpoint: as floquet_point gives them.
    module procedure chart_accepts
        chart_accepts = size(values) == 2 .and. i >= 1 .and. &
            i <= size(self%xs)*size(self%ys)
        if (chart_accepts) chart_accepts = point_values_valid(values(1), values(2))
    end procedure chart_accepts

    !> Stability chart over the grid of &chart: OUTDIR/NAME.chart.dat with one row per point,
    !! `x y max_modulus period` (CHART_INVALID where no analysis is possible, CHART_FAILED
    !! where it failed), a blank line after each x (gnuplot grid format).  The points are a
    !! sweep over threads and ranks, checkpointed to OUTDIR/NAME.chart.partial (see module
    !! sweep_engine; `options`: --resume and the checkpoint interval).  With `files` the file
    !! joins the run's others (see run_simulation); without it it is committed at once.
    module procedure run_chart
        type(out_files_t), target :: own
        type(out_files_t), pointer :: fs
        type(chart_task_t) :: task
        type(sweep_report_t) :: rep
        real(dp), allocatable :: vals(:, :), mods(:, :), pers(:, :)
        integer :: i, j, u, ios
        character(len=:), allocatable :: path

        fs => own
        if (present(files)) fs => files
        wall_seconds = 0.0_dp
        nstable = 0
        if (present(nfailed)) nfailed = 0
        call chart_task(d, task, stat)
        if (stat%code /= 0) return
        call sweep_run(task, 'chart', d%path, checkpoint_path(outdir, d%name, 'chart'), &
                       d%name//': chart', d%chart%nx*d%chart%ny, 2, vals, stat, options, rep, &
                       deck_text=d%text)
        if (present(report)) report = rep
        if (stat%code /= 0) return
        wall_seconds = rep%wall_seconds
        mods = reshape(vals(1, :), [d%chart%nx, d%chart%ny])
        pers = reshape(vals(2, :), [d%chart%nx, d%chart%ny])
        nstable = count(mods >= 0.0_dp .and. mods <= 1.0_dp + 1.0e-6_dp)
        if (present(nfailed)) nfailed = count(mods == CHART_FAILED)

        path = outdir//'/'//d%name//'.chart.dat'
        call fs%open(path, u, stat)
        if (stat%code /= 0) return
        write (u, '(a)', iostat=ios) '# bifilar stability chart of pure torsion: '// &
            trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# x = '//trim(d%chart%x)//', y = '// &
            trim(d%chart%y)//' (l, b, r over b''; amplitude in degrees; lambda in rad; '// &
            'inertia_ratio = I3/I1)'
        if (ios == 0) write (u, '(a)', iostat=ios) '# max_modulus and period = -1 where pure '// &
            'torsion is not possible (not a torsion scene, cables cannot reach), -2 where '// &
            'the analysis failed (e.g. more than '//itoa(FLOQUET_MAX_STEPS)//' steps)'
        call deck_echo(d, u, ios)
        if (ios == 0) write (u, '(a)', iostat=ios) '# x y max_modulus period'
        do i = 1, d%chart%nx
            do j = 1, d%chart%ny
                if (ios == 0) write (u, '(4es24.15e3)', iostat=ios) task%xs(i), task%ys(j), &
                    mods(i, j), pers(i, j)
            end do
            if (ios == 0) write (u, '(a)', iostat=ios) ''
        end do
        call fs%close(u, ios, stat)
        if (present(files)) return
        if (stat%code == 0) call own%commit(stat)
        if (stat%code /= 0) call own%discard()
    end procedure run_chart

end submodule stability_impl
