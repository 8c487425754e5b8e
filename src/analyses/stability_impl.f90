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
                       CHART_FAILED, point_values_valid, CHART_INVALID, &
                       FLOQUET_MAX_STEPS
    use output_io, only: out_files_t, write_kv
    use sweep_engine, only: sweep_task_t, sweep_run, sweep_options_t, sweep_report_t, &
        checkpoint_path
    use text, only: itoa, sci, fixed
    use unused_arg, only: unused
    use analysis_base, only: ranks_note, resume_note
    use kinds, only: pi
    use rig_groups, only: suspension_group_t, body_group_t, damping_group_t
    use platform_geometry, only: platform_t
    use platform_rig, only: platform_case_t, platform_case, platform_of
    use platform_floquet, only: platform_floquet_t, platform_floquet_analysis, &
                                platform_floquet_point
    implicit none

    !> The points of a platform's chart as a sweep (as chart_task_t for the bifilar): point
    !! k = (i, j), x index fastest; the deck's rig groups, each point's platform made from
    !! them with the two variables set (platform_chart_rig).
    type, extends(sweep_task_t) :: platform_chart_task_t
        type(suspension_group_t) :: sus
        type(body_group_t) :: bod
        type(damping_group_t) :: dmp
        character(len=16) :: x = '', y = ''
        real(dp), allocatable :: xs(:), ys(:)
        real(dp) :: amplitude = 0.0_dp, rtol = 0.0_dp
        integer :: method = 1
    contains
        procedure :: compute => platform_chart_point
        procedure :: accepts => platform_chart_accepts
    end type platform_chart_task_t



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
        type(platform_case_t) :: pc
        call unused(self)
        if (d%suspension%cables > 2) then
            ! a platform: the deck's own platform checked (platform_case)
            call platform_case(platform_of(d%suspension, d%body, d%damping), .false., &
                               d%cables%stiffness, d%cables%damping, pc, stat)
            if (stat%code /= 0) then
                stat%msg = 'analyses = ''chart'': '//stat%msg
                return
            end if
            call undamped_ready(d, stat)
            return
        end if
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
        type(platform_chart_task_t), allocatable :: pchart
        call unused(self)
        call unused(sweep)
        call unused(payload)
        if (d%suspension%cables > 2) then
            allocate (pchart)
            call platform_chart_task(d, pchart)
            stat%code = 0
            call move_alloc(pchart, task)
            return
        end if
        allocate (chart)
        call chart_task(d, chart, stat)
        call move_alloc(chart, task)
    end procedure chart_sweep_task

    !> The preconditions of analyses = 'floquet', checked before any computing: the cables
    !! can reach and pure torsion is an exact motion of the scene (ERR_DECK otherwise).
    module procedure floquet_ready
        type(pendulum_t) :: p
        type(platform_case_t) :: pc
        integer :: ivert
        if (d%suspension%cables > 2) then
            call platform_case(platform_of(d%suspension, d%body, d%damping), .false., &
                               d%cables%stiffness, d%cables%damping, pc, stat)
            return
        end if
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
        if (d%suspension%cables > 2) then
            call floquet_platform(d, outdir, fs, res, stat)
            if (present(files)) return
            if (stat%code == 0) call own%commit(stat)
            if (stat%code /= 0) call own%discard()
            return
        end if
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
        type(platform_chart_task_t) :: ptask
        type(sweep_report_t) :: rep
        real(dp), allocatable :: vals(:, :), mods(:, :), pers(:, :)
        integer :: i, j, u, ios
        character(len=:), allocatable :: path

        fs => own
        if (present(files)) fs => files
        wall_seconds = 0.0_dp
        nstable = 0
        if (present(nfailed)) nfailed = 0
        if (d%suspension%cables > 2) then
            ! a platform's chart: its own task (platform_chart_task_t), the same sweep
            call platform_chart_task(d, ptask)
            allocate (task%xs(size(ptask%xs)), task%ys(size(ptask%ys)))
            task%xs = ptask%xs
            task%ys = ptask%ys
            call sweep_run(ptask, 'chart', d%path, checkpoint_path(outdir, d%name, &
                           'chart'), d%name//': chart', d%chart%nx*d%chart%ny, 2, vals, stat, &
                           options, rep, deck_text=d%text)
        else
            call chart_task(d, task, stat)
            if (stat%code /= 0) return
            call sweep_run(task, 'chart', d%path, checkpoint_path(outdir, d%name, 'chart'), &
                           d%name//': chart', d%chart%nx*d%chart%ny, 2, vals, stat, options, &
                           rep, deck_text=d%text)
        end if
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
        if (d%suspension%cables > 2) then
            if (ios == 0) write (u, '(a)', iostat=ios) '# x = '//trim(d%chart%x)//', y = '// &
                trim(d%chart%y)//' (a platform of '//itoa(d%suspension%cables)//' cables: '// &
                'l, radius, cg_offset, cg_depth in deck units; amplitude of the yaw in '// &
                'degrees; inertia_ratio = I3/I1); period in the deck''s unit of time'
        else
            if (ios == 0) write (u, '(a)', iostat=ios) '# x = '//trim(d%chart%x)//', y = '// &
                trim(d%chart%y)//' (l, b, r over b''; amplitude in degrees; lambda in rad; '// &
                'inertia_ratio = I3/I1)'
        end if
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

    ! ------------------------------------------------------------------ a platform

    !> run_floquet for a platform (&suspension cables = 3, inextensible): the torsion at
    !! &floquet amplitude (of the yaw, degrees), its orbit found by shooting and its
    !! multipliers (module platform_floquet), into OUTDIR/NAME.floquet; res as the driver
    !! reads it (period, max_modulus, stable; the four multipliers, then the two trivial).
    subroutine floquet_platform(d, outdir, fs, res, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(out_files_t), intent(inout) :: fs
        type(floquet_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        type(platform_case_t) :: pc
        type(platform_floquet_t) :: pr
        real(dp) :: t0, t1
        integer :: u, k, ios
        call platform_case(platform_of(d%suspension, d%body, d%damping), .false., &
                           d%cables%stiffness, d%cables%damping, pc, stat)
        if (stat%code /= 0) return
        call cpu_time(t0)
        call platform_floquet_analysis(pc%pl, d%floquet%amplitude*deg, d%floquet%rtol, &
                                       method_of(d), pr, stat)
        call cpu_time(t1)
        if (stat%code /= 0) then
            stat%msg = 'floquet: '//stat%msg
            return
        end if
        res%period = pr%period
        res%max_modulus = pr%max_modulus
        res%stable = pr%stable
        res%multipliers(1:6) = pr%multipliers
        res%trivial(1:6) = pr%trivial
        res%orbit_closure = pr%orbit_closure
        res%trivial_residual = pr%trivial_residual
        res%steps = pr%steps
        res%rhs_evaluations = pr%rhs_evaluations
        call fs%open(outdir//'/'//d%name//'.floquet', u, stat)
        if (stat%code /= 0) return
        write (u, '(a)', iostat=ios) '# bifilar Floquet analysis of the torsion of a '// &
            'platform: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# a platform of '// &
            itoa(d%suspension%cables)//' inextensible cables; period in the deck''s unit of '// &
            'time; the orbit starts at rest at the turning point (x0, y0, yaw0) and comes '// &
            'to rest at half the period; multipliers of its monodromy matrix'
        call deck_echo(d, u, ios)
        call write_kv(u, 'period', pr%period, ios)
        call write_kv(u, 'max_modulus', pr%max_modulus, ios)
        call write_kv(u, 'stable', pr%stable, ios)
        call write_kv(u, 'amplitude_deg', d%floquet%amplitude, ios)
        call write_kv(u, 'rtol', d%floquet%rtol, ios)
        call write_kv(u, 'turning_point_x', pr%y0(1), ios)
        call write_kv(u, 'turning_point_y', pr%y0(2), ios)
        call write_kv(u, 'turning_point_yaw', pr%y0(3), ios)
        call write_kv(u, 'half_period_x', pr%yh(1), ios)
        call write_kv(u, 'half_period_y', pr%yh(2), ios)
        call write_kv(u, 'half_period_yaw', pr%yh(3), ios)
        call write_kv(u, 'orbit_closure', pr%orbit_closure, ios)
        call write_kv(u, 'shooting_iterations', pr%shooting_iterations, ios)
        call write_kv(u, 'continuation_steps', pr%continuation_steps, ios)
        call write_kv(u, 'trivial_residual', pr%trivial_residual, ios)
        call write_kv(u, 'cpu_seconds', t1 - t0, ios)
        call write_kv(u, 'steps', pr%steps, ios)
        call write_kv(u, 'rhs_evaluations', pr%rhs_evaluations, ios)
        if (ios == 0) write (u, '(a)', iostat=ios) '# multipliers: re im modulus trivial '// &
            '(trivial: 1 by structure -- time shift, energy)'
        do k = 1, 6
            if (ios == 0) write (u, '(3es24.15e3,2x,a)', iostat=ios) real(pr%multipliers(k)), &
                aimag(pr%multipliers(k)), abs(pr%multipliers(k)), &
                merge('yes', 'no ', pr%trivial(k))
        end do
        call fs%close(u, ios, stat)
    end subroutine floquet_platform

    !> The chart of a platform's deck as a sweep: its rig groups, the swept variables and
    !! their grids (deck units), &floquet amplitude and rtol.
    subroutine platform_chart_task(d, task)
        type(deck_t), intent(in) :: d
        type(platform_chart_task_t), intent(out) :: task
        integer :: i, j
        task%sus = d%suspension
        task%bod = d%body
        task%dmp = d%damping
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
        task%method = method_of(d)
    end subroutine platform_chart_task

    !> A platform's chart variable set in its groups (deck units): l every cable's length,
    !! radius the support's circle (the body's kept), cg_offset the mass centre's x in the
    !! body's frame, cg_depth its depth, inertia_ratio I3/I1, or the amplitude (degrees).
    pure subroutine set_platform_variable(name, value, sus, bod, amp_deg)
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: value
        type(suspension_group_t), intent(inout) :: sus
        type(body_group_t), intent(inout) :: bod
        real(dp), intent(inout) :: amp_deg
        select case (trim(name))
        case ('l')
            sus%l = value
        case ('radius')
            sus%radius = value
        case ('amplitude')
            amp_deg = value
        case ('cg_offset')
            bod%cg_offset = value
        case ('cg_depth')
            bod%cg_depth = value
        case ('inertia_ratio')
            bod%inertia(3) = value*bod%inertia(1)
        end select
    end subroutine set_platform_variable

    !> A platform's chart point i: values = [max_modulus, period] (platform_floquet_point's
    !! sentinels).  Never fails itself.
    subroutine platform_chart_point(self, i, values, stat)
        class(platform_chart_task_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: stat
        type(suspension_group_t) :: sus
        type(body_group_t) :: bod
        real(dp) :: amp
        integer :: ix, iy
        stat%code = 0
        ix = mod(i - 1, size(self%xs)) + 1
        iy = (i - 1)/size(self%xs) + 1
        sus = self%sus
        bod = self%bod
        amp = self%amplitude
        call set_platform_variable(self%x, self%xs(ix), sus, bod, amp)
        call set_platform_variable(self%y, self%ys(iy), sus, bod, amp)
        values = CHART_INVALID
        if (.not. (amp > 0.0_dp .and. amp < 180.0_dp)) return
        call platform_floquet_point(platform_of(sus, bod, self%dmp), amp, self%rtol, &
                                    self%method, values(1), values(2))
    end subroutine platform_chart_point

    !> A platform's chart point i's values read back from a checkpoint: as
    !! platform_floquet_point gives them.
    logical function platform_chart_accepts(self, i, values)
        class(platform_chart_task_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(in) :: values(:)
        platform_chart_accepts = size(values) == 2 .and. i >= 1 .and. &
            i <= size(self%xs)*size(self%ys)
        if (platform_chart_accepts) platform_chart_accepts = &
            point_values_valid(values(1), values(2))
    end function platform_chart_accepts

end submodule stability_impl
