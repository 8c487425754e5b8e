!> The implementation of analysis tensor (submodule of tensor): the preconditions, the run
!! (the projection solution, the exact fit, the amplitude limits, the Monte Carlo, the
!! plan) and the output files.
submodule (tensor) tensor_impl
    use kinds, only: deg, pi
    use status, only: set_error, STATUS_OK, ERR_DECK, ERR_NUMERIC, ERR_MODEL
    use work_estimate, only: GYRATION_MAX
    use text, only: itoa, sci, fixed, rshort
    use deck, only: deck_echo
    use output_io, only: write_kv, all_finite
    use fast_format, only: es_field
    use rig, only: rig_t
    use deck_runs, only: accuracy_of
    use monte_carlo, only: monte_carlo_run, MC_TENSOR
    use measurement, only: measurement_t, hang_t
    use measurement_read, only: read_hangs, hang_defaults, table_name
    use hang_model, only: tensor_entries, hang_rig, torsion_mode, torsion_mode_t
    use tensor_fit, only: tensor_problem_t, tensor_fit_t, tensor_plan_t, tensor_mc_task_t, &
        problem_of, check_directions, projection, fit_tensor, amplitude_limits, plan_hangs, &
        tensor_mc_payload, tensor_mc_task, amplitude_parts, DRIFT_MAX, DRIFT_CYCLES, &
        MC_ESTIMATES, MC_PARTS
    use tensor_checks, only: check_moments, near_parallel_hangs
    use unused_arg, only: unused
    use analysis_base, only: ranks_note, resume_note
    implicit none

    !> The names of the six entries, in their order.
    character(len=4), parameter :: ENTRY_NAMES(6) = ['J_xx', 'J_yy', 'J_zz', 'J_xy', &
                                                     'J_xz', 'J_yz']

contains

    !> The deck's &body principal moments as a tensor along the body frame's axes (the
    !! start of the checks and of a plan without hangs).
    pure function deck_tensor(d) result(x)
        type(deck_t), intent(in) :: d
        real(dp) :: x(6)
        x = [d%body%inertia(1), d%body%inertia(2), d%body%inertia(3), 0.0_dp, 0.0_dp, 0.0_dp]
    end function deck_tensor

    !> The preconditions of analyses = 'tensor' (see the interface).
    module procedure tensor_ready
        type(measurement_t) :: set
        type(hang_t) :: h0
        type(rig_t) :: rg
        type(torsion_mode_t) :: md
        real(dp) :: cond
        logical :: have_cg
        integer :: h
        stat%code = STATUS_OK
        if (d%measurement%tare_i1 /= 0.0_dp .or. d%measurement%u_tare_i1 /= 0.0_dp .or. &
            d%measurement%tare_mass /= 0.0_dp .or. d%measurement%added_inertia /= 0.0_dp .or. &
            d%measurement%u_added_inertia /= 0.0_dp) then
            call set_error(stat, ERR_DECK, 'analyses = ''tensor'': &measurement tare_i1, '// &
                'u_tare_i1, tare_mass, added_inertia: a tare or added inertia about '// &
                'identify''s single axis, which tensor cannot take (what hangs with the body '// &
                'turns with it from hang to hang); allowed: none of them in a deck with '// &
                'analyses = ''tensor'', and the fixture as &tensor fixture_* (fixture_mass, '// &
                'fixture_cg, fixture_inertia, their u_fixture_*, fixture_frame): it enters '// &
                'each hang''s model')
            return
        end if
        if (d%tensor%estimates_cg() .and. len_trim(d%tensor%hangs) == 0 .and. &
            d%tensor%plan == 0) then
            call set_error(stat, ERR_DECK, '&tensor estimate = ''tensor cg'': no table of '// &
                'hangs; allowed: hangs = ''FILE'' (the mass centre is fitted to its periods '// &
                'and attitudes), or plan = N (hangs planned for it)')
            return
        end if
        if (trim(d%scene%model) /= 'kane') then
            call set_error(stat, ERR_DECK, 'analyses = ''tensor'': &scene model = '''// &
                trim(d%scene%model)//''': tensor fits the paper''s model; allowed: '// &
                'model = ''kane''')
            return
        end if
        if (len_trim(d%tensor%hangs) > 0) then
            if (.not. (d%body%gave('inertia') .or. d%body%gave('size'))) then
                call set_error(stat, ERR_DECK, 'analyses = ''tensor'': not given: &body '// &
                    'inertia (start values) or size (the diameter of a sphere that holds '// &
                    'the body): without either a tensor N^2 times too large (totals of N '// &
                    'cycles typed as periods) cannot be told from the right one; allowed: '// &
                    '&body inertia = the principal moments you expect (within a factor 30), '// &
                    'or size = d')
                return
            end if
            call read_hangs(d%tensor, d%suspension, d%body, set, stat)
            if (stat%code /= STATUS_OK) return
            call check_directions(set%releases%hang, table_name(d%tensor), cond, stat)
            if (stat%code /= STATUS_OK) return
            do h = 1, size(set%releases)
                call hang_rig(d%body%mass, d%suspension%g, set%releases(h)%hang, &
                              deck_tensor(d), rg, stat)
                ! (on a platform the body alone need not rest stably: the platform, a
                ! fixture, holds it; the fit's model judges what hangs)
                if (stat%code == STATUS_OK .and. rg%cables <= 2) call torsion_mode(rg, md, stat)
                if (stat%code /= STATUS_OK) then
                    stat%msg = table_name(d%tensor)//': hang '//itoa(set%releases(h)%id)//' (line '// &
                        itoa(set%releases(h)%line)//'): '//stat%msg
                    return
                end if
                call period_in_reach(h, rg, stat)
                if (stat%code /= STATUS_OK) return
            end do
        end if
        if (d%tensor%plan > 0 .or. d%tensor%plan_add > 0) then
            call hang_defaults(d%suspension, d%body, h0, have_cg)
            if (len_trim(d%tensor%hangs) > 0 .and. .not. have_cg) then
                h0 = set%releases(1)%hang
                have_cg = .true.
            end if
            if (.not. have_cg) then
                call set_error(stat, ERR_DECK, 'not given: &body the mass centre (cg_depth '// &
                    'and cg_offset, or r and lambda); a deck with analyses = ''tensor'' '// &
                    'gives every physical input itself (the defaults are the paper''s '// &
                    'dimensionless scene); allowed: &body cg_depth, cg_offset for the '// &
                    'planned hangs (&tensor plan)')
                return
            end if
            call hang_rig(d%body%mass, d%suspension%g, h0, deck_tensor(d), rg, stat)
            if (stat%code == STATUS_OK .and. rg%cables <= 2) call torsion_mode(rg, md, stat)
            if (stat%code /= STATUS_OK) then
                stat%msg = '&tensor plan = '//itoa(d%tensor%plan)//': the deck''s rig: '// &
                    stat%msg
                return
            end if
        end if
    contains

        !> A period (per cycle) more than GYRATION_MAX times the hang's rig's
        !! period with the body's mass at its cable attachments, 2 pi (l b'/(g b))^(1/2), is
        !! refused before any computing (times in ms would simulate for minutes).
        subroutine period_in_reach(h, rg, st)
            integer, intent(in) :: h
            type(rig_t), intent(in) :: rg
            type(status_t), intent(inout) :: st
            real(dp) :: ta
            integer :: i
            ta = 2.0_dp*pi*sqrt(0.5_dp*(rg%l + rg%l_prime)*rg%b_prime/(rg%g*rg%b))
            do i = 1, size(set%obs)
                if (set%obs(i)%release /= h) cycle
                if (set%obs(i)%period > GYRATION_MAX*ta) then
                    call set_error(st, ERR_MODEL, table_name(d%tensor)//': line '// &
                        itoa(set%obs(i)%line)//': hang '//itoa(set%releases(h)%id)// &
                        ': a period of '//sci(set%obs(i)%period, 4)//' s (per cycle) is '// &
                        itoa(nint(set%obs(i)%period/ta))//' times that of this hang''s '// &
                        'rig with the body''s mass at its cable attachments (2 pi (l '// &
                        'b_prime/(g b))^(1/2) = '//sci(ta, 4)//' s), beyond the '// &
                        itoa(nint(GYRATION_MAX))//' times any bifilar body gives; likely: '// &
                        'times in other units than s (ms), totals of cycles with a wrong '// &
                        'cycles column, or lengths in other units than the deck''s')
                    return
                end if
            end do
        end subroutine period_in_reach

    end procedure tensor_ready

    !> Run analyses = 'tensor' (see the interface).
    module procedure run_tensor
        type(measurement_t) :: set
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit
        type(tensor_plan_t) :: plan
        type(tensor_mc_task_t) :: task
        type(sweep_report_t) :: rep
        type(hang_t) :: h0
        real(dp), allocatable :: drift(:), limit(:), payload(:), parts(:, :)
        real(dp) :: c0, c1, x_proj(6), cond, mean(MC_ESTIMATES), sdev(MC_ESTIMATES), x(6)
        real(dp) :: u_x_mc(6), u_moments_mc(3), u_axes_mc(3), u_plan, plan_cycles
        real(dp), allocatable :: u_hang(:)
        logical :: have_cg
        integer :: i, h, plan_timings, first_id
        character(len=:), allocatable :: line
        call cpu_time(c0)
        u_x_mc = 0.0_dp
        u_moments_mc = 0.0_dp
        u_axes_mc = 0.0_dp
        rep%note = ''
        res%warning = ''
        res%plan_file = ''
        allocate (res%warnings(0))
        stat%code = STATUS_OK
        if (len_trim(d%tensor%hangs) > 0) then
            call read_hangs(d%tensor, d%suspension, d%body, set, stat)
            if (stat%code /= STATUS_OK) return
            call check_directions(set%releases%hang, table_name(d%tensor), cond, stat)
            if (stat%code /= STATUS_OK) return
            call problem_of(d%tensor, d%suspension, d%body, accuracy_of(d), set, prob)
            call projection(prob, x_proj, stat)
            if (stat%code /= STATUS_OK) return
            call fit_tensor(prob, x_proj, fit, stat)
            if (stat%code /= STATUS_OK) then
                call no_body(stat)
                return
            end if
            prob%dcg = fit%dcg
            ! the amplitude limits at the fit: refuse a period that is not defined, carry
            ! the drift of the others as the uncertainty of their definition, fit again
            allocate (drift(size(prob%rows)), limit(size(prob%hangs)))
            call amplitude_limits(prob, fit%x, drift, limit, stat)
            if (stat%code /= STATUS_OK) return
            do i = 1, size(prob%rows)
                if (drift(i) > DRIFT_MAX) then
                    h = prob%rows(i)%release
                    call set_error(stat, ERR_DECK, table_name(d%tensor)//': line '// &
                        itoa(prob%rows(i)%line)//': hang '//itoa(prob%hangs(h)%id)// &
                        ' at amplitude = '//rshort(prob%rows(i)%amplitude)//' deg: its '// &
                        'period is not defined well enough: theta4''s maxima drift by '// &
                        sci(drift(i), 1)//' of the period over the first '// &
                        itoa(DRIFT_CYCLES)//' cycles (the torsion couples with tilting and '// &
                        'sway); allowed: a drift <= '//rshort(DRIFT_MAX)//', amplitudes up '// &
                        'to '//degrees(limit(h))//' deg for this hang, or 0 (small amplitude)')
                    return
                end if
            end do
            if (any(drift > 0.0_dp)) then
                prob%u_def = drift*fit%model_period/sqrt(3.0_dp)
                x = fit%x
                call fit_tensor(prob, x, fit, stat)
                if (stat%code /= STATUS_OK) then
                    call no_body(stat)
                    return
                end if
                prob%dcg = fit%dcg
            end if
            fit%x_proj = x_proj
            fit%projection_difference = maxval(abs(x_proj - fit%x))/maxval(fit%moments)
            ! what no body can have, refused; the hangs nearly parallel, said
            call check_moments(fit%moments, d%body%mass, d%body%size, d%body%inertia, &
                               d%body%gave('inertia'), line, stat)
            if (stat%code /= STATUS_OK) return
            call push_warning(line)
            call push_warning(near_parallel_hangs(prob%hangs, table_name(d%tensor)))
            fit%condition = cond
            res%fitted = .true.
            res%moments = fit%moments
            res%u_moments = fit%u_moments
            res%chi2 = fit%chi2
            res%p_value = fit%p_value
            res%dof = fit%dof
            res%projection_difference = fit%projection_difference
            res%hangs = size(prob%hangs)
            res%rows = size(prob%rows)
            if (d%tensor%monte_carlo > 0) then
                allocate (parts(MC_PARTS, size(prob%case_hang)))
                call amplitude_parts(prob, fit%x, parts, stat)
                if (stat%code /= STATUS_OK) return
                payload = tensor_mc_payload(prob, fit, d%tensor%seed, parts)
                call tensor_mc_task(d%tensor, d%suspension, d%body, accuracy_of(d), payload, task, &
                                stat)
                if (stat%code /= STATUS_OK) return
                call monte_carlo_run(task, d, d%tensor%monte_carlo, payload, mean, sdev, stat, &
                                     outdir, options, rep, files, MC_TENSOR)
                if (stat%code /= STATUS_OK) return
                res%mc_samples = d%tensor%monte_carlo
                u_x_mc = sdev(1:6)
                u_moments_mc = sdev(7:9)
                u_axes_mc = [norm2(sdev(10:11)), norm2(sdev(12:13)), norm2(sdev(14:15))]/deg
                res%u_moments_mc = u_moments_mc
                if (prob%est_cg) then
                    res%cg_mc = prob%origin + mean(16:18)
                    res%u_cg_mc = sdev(16:18)
                end if
            end if
            if (fit%dof > 0 .and. fit%p_value < 0.05_dp .and. .not. fit%scatter) then
                h = maxloc(abs(fit%resid), 1)
                res%warning = 'tensor: chi2 = '//fixed(fit%chi2, 2)//' for '//itoa(fit%dof)// &
                    ' degrees of freedom is improbable (p = '//sci(fit%p_value, 1)// &
                    ' < 0.05): the hangs disagree with the fit beyond their uncertainties; '// &
                    'hang '//itoa(prob%hangs(h)%id)//' (line '//itoa(prob%hangs(h)%line)// &
                    ') has the largest normalised residual, '//fixed(fit%resid(h), 2)// &
                    ': check its timing, orientation and rig; the u of each hang''s rows '// &
                    'are inflated by the Birge ratio '//fixed(fit%birge, 2)
            end if
        end if
        if (d%tensor%plan > 0 .or. d%tensor%plan_add > 0) then
            call hang_defaults(d%suspension, d%body, h0, have_cg)
            plan_cycles = 1.0_dp
            plan_timings = 1
            if (res%fitted) then
                if (.not. have_cg) h0 = prob%hangs(1)
                x = fit%x
                ! the table's timings: each hang's timing u (its rows' u_period over cycles,
                ! together), the median of them for a planned hang, the median cycles and
                ! rows per hang
                call table_timing(prob, fit, u_hang, u_plan, plan_cycles, plan_timings)
            else
                call problem_of(d%tensor, d%suspension, d%body, accuracy_of(d), set_empty(), prob)
                x = deck_tensor(d)
                u_plan = d%tensor%u(7)
            end if
            if (d%tensor%plan_add > 0) then
                call plan_hangs(prob, h0, u_plan, x, d%tensor%plan_add, plan, stat, &
                                prob%hangs, u_hang)
            else
                call plan_hangs(prob, h0, u_plan, x, d%tensor%plan, plan, stat)
            end if
            if (stat%code /= STATUS_OK) return
            res%plan = plan%n
            res%plan_file = outdir//'/'//d%name//'.plan.csv'
        end if
        if (present(report)) report = rep
        call cpu_time(c1)
        res%cpu_seconds = c1 - c0
        call write_tensor(d, outdir, res, fit, prob, drift, limit, plan, u_x_mc, &
                          u_moments_mc, u_axes_mc, files, stat)
        if (stat%code /= STATUS_OK) return
        if (res%fitted) call write_data(d, outdir, fit, prob, files, stat)
        if (stat%code /= STATUS_OK) return
        if (res%fitted) call write_tensor_certificate(d, outdir, res, fit, prob, drift, limit, &
                                                      u_x_mc, u_moments_mc, files, stat)
        if (stat%code /= STATUS_OK) return
        if (res%plan > 0) then
            first_id = 1
            if (d%tensor%plan_add > 0) first_id = maxval(prob%hangs%id) + 1
            call write_plan(d, res%plan_file, plan, x, plan_cycles, plan_timings, first_id, &
                            files, stat)
        end if
    contains
        !> A fit that went where no body is (a tensor not positive definite): ERR_MODEL
        !! with the likely cause.
        subroutine no_body(st)
            type(status_t), intent(inout) :: st
            if (index(st%msg, 'not positive definite') == 0) return
            st%code = ERR_MODEL
            st%msg = table_name(d%tensor)//': the fit of the tensor: '//st%msg//': the '// &
                'periods ask for a tensor no rigid body has, they disagree with each other; '// &
                'likely: totals of different numbers of cycles typed as periods (the cycles '// &
                'column), a direction (up, along) mistyped; allowed: periods of one body'
        end subroutine no_body
        !> One more warning line ('' none).
        subroutine push_warning(w)
            character(len=*), intent(in) :: w
            type(tensor_line_t) :: one
            if (len(w) == 0) return
            one%s = w
            res%warnings = [res%warnings, one]
        end subroutine push_warning
    end procedure run_tensor

    !> An amplitude limit as text: two significant digits.
    function degrees(a) result(s)
        real(dp), intent(in) :: a
        character(len=:), allocatable :: s
        if (a >= 10.0_dp) then
            s = itoa(nint(a))
        else
            s = fixed(a, merge(1, 2, a >= 1.0_dp))
        end if
    end function degrees

    !> The table's timings for a plan: per hang the timing u of its rows together
    !! ((sum of u_row^-2)^(-1/2), 0 when its rows state none); for a planned hang the median
    !! of them, the median cycles of a row and the median rows of a hang.
    subroutine table_timing(prob, fit, u_hang, u_plan, cycles, timings)
        type(tensor_problem_t), intent(in) :: prob
        type(tensor_fit_t), intent(in) :: fit
        real(dp), allocatable, intent(out) :: u_hang(:)
        real(dp), intent(out) :: u_plan, cycles
        integer, intent(out) :: timings
        real(dp), allocatable :: w(:)
        integer :: h, nh
        nh = size(prob%hangs)
        allocate (u_hang(nh), w(nh))
        do h = 1, nh
            associate (ur => pack(fit%u_row, prob%rows%release == h))
                u_hang(h) = 0.0_dp
                if (all(ur > 0.0_dp)) u_hang(h) = 1.0_dp/sqrt(sum(1.0_dp/ur**2))
                w(h) = real(size(ur), dp)
            end associate
        end do
        u_plan = median(u_hang)
        timings = max(1, nint(median(w)))
        cycles = median(prob%rows%cycles)
    contains
        pure real(dp) function median(v)
            real(dp), intent(in) :: v(:)
            real(dp) :: s(size(v)), tmp
            integer :: i, j, n
            s = v
            n = size(s)
            do i = 2, n
                tmp = s(i)
                j = i - 1
                do while (j >= 1)
                    if (s(j) <= tmp) exit
                    s(j + 1) = s(j)
                    j = j - 1
                end do
                s(j + 1) = tmp
            end do
            median = 0.5_dp*(s((n + 1)/2) + s(n/2 + 1))
        end function median
    end subroutine table_timing

    !> A set of no hangs (a plan without a table).
    function set_empty() result(set)
        type(measurement_t) :: set
        allocate (set%releases(0), set%obs(0))
    end function set_empty

    !> The task of tensor's Monte Carlo (see the interface).
    module procedure tensor_sweep_task
        allocate (tensor_mc_task_t :: task)
        select type (task)
        type is (tensor_mc_task_t)
            call tensor_mc_task(d%tensor, d%suspension, d%body, accuracy_of(d), payload, task, &
                                stat)
        end select
    end procedure tensor_sweep_task

    !> Reals as 'a, b, c' in full precision.
    function reals_text(v) result(s)
        real(dp), intent(in) :: v(:)
        character(len=:), allocatable :: s
        character(len=32) :: buf
        integer :: k
        s = ''
        do k = 1, size(v)
            write (buf, '(es25.16e3)') v(k)
            if (k > 1) s = s//', '
            s = s//trim(adjustl(buf))
        end do
    end function reals_text

    !> OUTDIR/NAME.tensor: key = value lines, then the budget.
    subroutine write_tensor(d, outdir, res, fit, prob, drift, limit, plan, u_x_mc, &
                            u_moments_mc, u_axes_mc, files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(tensor_result_t), intent(in) :: res
        type(tensor_fit_t), intent(in) :: fit
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in), allocatable :: drift(:), limit(:)
        type(tensor_plan_t), intent(in) :: plan
        real(dp), intent(in) :: u_x_mc(6), u_moments_mc(3), u_axes_mc(3)
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        real(dp) :: corr(6, 6)
        integer :: u, ios, k, j, h, i
        character(len=24) :: f(7)
        character(len=:), allocatable :: id
        stat%code = STATUS_OK
        if (res%fitted) then
            if (.not. all_finite([fit%x, fit%u_x, reshape(fit%cov, [36]), fit%moments, &
                                  fit%u_moments, reshape(fit%axes, [9]), fit%u_axes, fit%chi2, &
                                  fit%condition, fit%projection_difference, fit%iv, fit%u_iv, &
                                  fit%resid, fit%iv_fit, fit%model_period, drift, limit, &
                                  fit%k95, fit%x_proj])) then
                call set_error(stat, ERR_NUMERIC, 'tensor: a result is not finite')
                return
            end if
            if (res%mc_samples > 0) then
                if (.not. all_finite([u_x_mc, u_moments_mc, u_axes_mc])) then
                    call set_error(stat, ERR_NUMERIC, 'tensor: a Monte Carlo result is not '// &
                                   'finite')
                    return
                end if
            end if
        end if
        call files%open(outdir//'/'//d%name//'.tensor', u, stat)
        if (stat%code /= STATUS_OK) return
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar tensor: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# the inertia tensor about the mass '// &
            'centre in the body frame (deck units: mass x length^2; J_xy = -int x y dm), '// &
            'standard uncertainties u_, periods in s, angles in degrees'
        call deck_echo(d, u, ios)
        if (res%fitted) then
            do k = 1, 6
                call write_kv(u, ENTRY_NAMES(k), fit%x(k), ios)
                call write_kv(u, 'u_'//ENTRY_NAMES(k), fit%u_x(k), ios)
            end do
            do k = 1, 6
                do j = 1, 6
                    corr(k, j) = merge(1.0_dp, 0.0_dp, k == j)
                    if (k /= j .and. fit%u_x(k) > 0.0_dp .and. fit%u_x(j) > 0.0_dp) &
                        corr(k, j) = max(-1.0_dp, min(1.0_dp, &
                                                     fit%cov(k, j)/(fit%u_x(k)*fit%u_x(j))))
                end do
                call write_kv(u, 'correlation('//itoa(k)//',:)', reals_text(corr(k, :)), ios)
            end do
            call write_kv(u, 'I_principal', reals_text(fit%moments), ios)
            call write_kv(u, 'u_I_principal', reals_text(fit%u_moments), ios)
            do k = 1, 3
                call write_kv(u, 'axis_'//itoa(k), reals_text(fit%axes(:, k)), ios)
            end do
            call write_kv(u, 'u_axis_deg', reals_text(fit%u_axes), ios)
            if (prob%est_cg) call write_cg(u, ios)
            call write_kv(u, 'chi2', fit%chi2, ios)
            call write_kv(u, 'dof', fit%dof, ios)
            call write_kv(u, 'condition', fit%condition, ios)
            call write_kv(u, 'projection_difference', fit%projection_difference, ios)
            call write_kv(u, 'p_value', fit%p_value, ios)
            ! the fit's self-check (module tensor_fit): its u inflated when inconsistent
            if (fit%tested) then
                call write_kv(u, 'fit_consistency', trim(merge('consistent  ', 'inconsistent', &
                                                               fit%consistent)), ios)
                call write_kv(u, 'fit_birge_ratio', fit%birge, ios)
            else
                call write_kv(u, 'fit_consistency', 'not tested', ios)
            end if
            call write_kv(u, 'k95_I_principal', reals_text(fit%k95), ios)
            call write_kv(u, 'U95_I_principal', reals_text(fit%k95*fit%u_moments), ios)
            call write_kv(u, 'J_projection', reals_text(fit%x_proj), ios)
            call write_kv(u, 'hangs', size(prob%hangs), ios)
            call write_kv(u, 'rows', size(prob%rows), ios)
            call write_kv(u, 'iterations', fit%iterations, ios)
            call write_kv(u, 'u_period_source', trim(merge('scatter', 'stated ', fit%scatter)), &
                          ios)
            if (fit%scatter) call write_kv(u, 'u_period_from_scatter', fit%u_scatter, ios)
            call write_kv(u, 'drift_max', DRIFT_MAX, ios)
            do h = 1, size(prob%hangs)
                id = itoa(prob%hangs(h)%id)
                call write_kv(u, 'I_vertical('//id//')', fit%iv(h), ios)
                call write_kv(u, 'u_I_vertical('//id//')', fit%u_iv(h), ios)
                call write_kv(u, 'residual('//id//')', fit%resid(h), ios)
            end do
            do h = 1, size(prob%hangs)
                call write_kv(u, 'amplitude_limit('//itoa(prob%hangs(h)%id)//')', limit(h), ios)
            end do
            do i = 1, size(prob%rows)
                call write_kv(u, 'model_period('//itoa(i)//')', fit%model_period(i), ios)
                call write_kv(u, 'drift('//itoa(i)//')', drift(i), ios)
            end do
            if (res%mc_samples > 0) then
                call write_kv(u, 'monte_carlo_samples', res%mc_samples, ios)
                call write_kv(u, 'monte_carlo_seed', d%tensor%seed, ios)
                do k = 1, 6
                    call write_kv(u, 'u_'//ENTRY_NAMES(k)//'_monte_carlo', u_x_mc(k), ios)
                end do
                call write_kv(u, 'u_I_principal_monte_carlo', reals_text(u_moments_mc), ios)
                call write_kv(u, 'u_axis_deg_monte_carlo', reals_text(u_axes_mc), ios)
                if (prob%est_cg) then
                    call write_kv(u, 'cg_monte_carlo_mean', reals_text(res%cg_mc), ios)
                    call write_kv(u, 'u_cg_monte_carlo', reals_text(res%u_cg_mc), ios)
                end if
            end if
        end if
        if (res%plan > 0) then
            call write_kv(u, 'plan_hangs', plan%n, ios)
            call write_kv(u, 'plan_file', res%plan_file, ios)
            call write_kv(u, 'plan_trace', plan%trace, ios)
            call write_kv(u, 'plan_u', reals_text(plan%u_x), ios)
            if (prob%est_cg) call write_kv(u, 'plan_u_cg', reals_text(plan%u_cg), ios)
        end if
        call write_kv(u, 'cpu_seconds', res%cpu_seconds, ios)
        if (res%fitted) then
            if (ios == 0) write (u, '(a)', iostat=ios) '# budget (first order, GUM): input, '// &
                'its standard uncertainty (direction in degrees), and what it adds to the u '// &
                'of J_xx J_yy J_zz J_xy J_xz J_yz (their root sum of squares over the inputs '// &
                'is the u, correlations aside)'
            do k = 1, size(fit%budget)
                call es_field(fit%budget(k)%u, 8, f(1)(1:16))
                do j = 1, 6
                    call es_field(fit%budget(k)%contribution(j), 8, f(j + 1)(1:16))
                end do
                if (ios == 0) write (u, '(a)', iostat=ios) fit%budget(k)%input(1:18)// &
                    f(1)(1:16)//f(2)(1:16)//f(3)(1:16)//f(4)(1:16)//f(5)(1:16)//f(6)(1:16)// &
                    f(7)(1:16)
            end do
        end if
        call files%close(u, ios, stat)
    contains
        !> The mass centre fitted with the tensor: cg (body frame), its u, its shift from
        !! where the table put it, the joint correlation of (J_xx ... J_yz, cg_x, cg_y, cg_z),
        !! each attitude's normalised residual.
        subroutine write_cg(un, io)
            integer, intent(in) :: un
            integer, intent(inout) :: io
            real(dp) :: c9(9, 9), s9(9)
            integer :: a, b, m
            call write_kv(un, 'cg', reals_text(prob%origin + fit%dcg), io)
            call write_kv(un, 'u_cg', reals_text(fit%u_dcg), io)
            call write_kv(un, 'cg_shift', reals_text(fit%dcg), io)
            s9 = sqrt(max(0.0_dp, [(fit%cov_all(a, a), a=1, 9)]))
            do a = 1, 9
                do b = 1, 9
                    c9(a, b) = merge(1.0_dp, 0.0_dp, a == b)
                    if (a /= b .and. s9(a) > 0.0_dp .and. s9(b) > 0.0_dp) c9(a, b) = &
                        max(-1.0_dp, min(1.0_dp, fit%cov_all(a, b)/(s9(a)*s9(b))))
                end do
                call write_kv(un, 'correlation_tensor_cg('//itoa(a)//',:)', &
                              reals_text(c9(a, :)), io)
            end do
            do m = 1, size(prob%att_hang)
                call write_kv(un, 'attitude_residual('//itoa(prob%hangs(prob%att_hang(m))%id)// &
                              ')', fit%att_resid(m), io)
            end do
        end subroutine write_cg
    end subroutine write_tensor

    !> OUTDIR/NAME.tensor.dat: per hang its id, the fitted tensor's vertical moment, the one
    !! its periods measure, that one's u, the normalised residual; line 1 the title.
    subroutine write_data(d, outdir, fit, prob, files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(tensor_fit_t), intent(in) :: fit
        type(tensor_problem_t), intent(in) :: prob
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        integer :: u, ios, h
        character(len=22) :: f(2)
        character(len=16) :: e(2)
        call files%open(outdir//'/'//d%name//'.tensor.dat', u, stat)
        if (stat%code /= STATUS_OK) return
        ios = 0
        write (u, '(a)', iostat=ios) '# '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# bifilar tensor, per hang (deck units): '// &
            'hang I_fitted (u . J u of the fit) I_measured (what its periods give) '// &
            'u_I_measured residual (normalised)'
        do h = 1, size(prob%hangs)
            call es_field(fit%iv_fit(h), 14, f(1))
            call es_field(fit%iv(h), 14, f(2))
            call es_field(fit%u_iv(h), 8, e(1))
            call es_field(fit%resid(h), 8, e(2))
            if (ios == 0) write (u, '(i8,4(1x,a))', iostat=ios) prob%hangs(h)%id, f(1), f(2), &
                e(1), e(2)
        end do
        call files%close(u, ios, stat)
    end subroutine write_data

    !> OUTDIR/NAME.plan.csv: the planned hangs as a table of hangs to copy (the periods the
    !! tensor x predicts at small amplitude, to be replaced by the timed ones).
    subroutine write_plan(d, path, plan, x, cycles, timings, first_id, files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: path
        type(tensor_plan_t), intent(in) :: plan
        real(dp), intent(in) :: x(6)
        real(dp), intent(in) :: cycles          !! cycles of each timing
        integer, intent(in) :: timings          !! timings of each hang
        integer, intent(in) :: first_id         !! the first planned hang's number
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        integer :: u, ios, k, m
        real(dp) :: up(3), al(3)
        character(len=:), allocatable :: crit
        crit = 'trace of the covariance of the tensor, '//sci(plan%trace, 3)//' (deck units '// &
            'squared)'
        if (d%tensor%estimates_cg()) crit = 'trace of the covariance of the tensor and of '// &
            'the mass centre ((m b'')^2 times the latter''s), '//sci(plan%trace, 3)// &
            ' (deck units squared), each hang with its attitude measured'
        call files%open(path, u, stat)
        if (stat%code /= STATUS_OK) return
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar tensor plan: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# '//itoa(plan%n)//' hangs '// &
            trim(merge('added to the table ', '                   ', d%tensor%plan_add > 0))// &
            'among the face, edge and corner directions of the body frame that minimise the '// &
            crit//', under the deck''s uncertainties, each timed '//itoa(timings)// &
            ' time'//trim(merge('s', ' ', timings /= 1))//' over '//rshort(cycles)//' cycle'// &
            trim(merge('s', ' ', cycles /= 1.0_dp))
        if (ios == 0) write (u, '(a)', iostat=ios) '# period: the period the tensor '// &
            trim(reals_short(x))//' predicts at small amplitude on the deck''s rig: replace '// &
            'it by the timed one (and cycles, amplitude by yours)'
        if (ios == 0) write (u, '(a)', iostat=ios) &
            'hang,up_x,up_y,up_z,along_x,along_y,along_z,period,cycles,amplitude'
        do k = 1, plan%n
            up = plan%up(:, k)/maxval(abs(plan%up(:, k)))
            al = plan%along(:, k)/maxval(abs(plan%along(:, k)))
            do m = 1, timings
                if (ios == 0) write (u, '(a)', iostat=ios) itoa(first_id + k - 1)//','// &
                    ints(up)//','//ints(al)//','//fixed(cycles*plan%period(k), 6)//','// &
                    rshort(cycles)//',0'
            end do
        end do
        call files%close(u, ios, stat)
    contains
        function ints(v) result(s)
            real(dp), intent(in) :: v(3)
            character(len=:), allocatable :: s
            s = itoa(nint(v(1)))//','//itoa(nint(v(2)))//','//itoa(nint(v(3)))
        end function ints
        function reals_short(v) result(s)
            real(dp), intent(in) :: v(:)
            character(len=:), allocatable :: s
            integer :: m
            s = '('
            do m = 1, size(v)
                if (m > 1) s = s//', '
                s = s//sci(v(m), 4)
            end do
            s = s//')'
        end function reals_short
    end subroutine write_plan

    ! ------------------------------------------------------------ the analysis for the driver

    !> The preconditions (tensor_ready).
    module procedure tensor_analysis_ready
        call unused(self)
        call tensor_ready(d, stat)
    end procedure tensor_analysis_ready

    !> The run (run_tensor into the run's files); the Monte Carlo's warning and the result's
    !! warning kept.
    module procedure tensor_analysis_run
        integer :: i
        call run_tensor(d, outdir, self%res, stat, files, options, self%rep)
        call self%add_report_warning(self%rep)
        if (stat%code /= 0) return
        if (allocated(self%res%warnings)) then
            do i = 1, size(self%res%warnings)
                call self%add_warning(self%res%warnings(i)%s)
            end do
        end if
        if (allocated(self%res%warning)) then
            if (len(self%res%warning) > 0) call self%add_warning(self%res%warning)
        end if
    end procedure tensor_analysis_run

    !> The summary line's part of analysis tensor: the principal moments with their u, the
    !! chi-square, how far the projection solution lies, the Monte Carlo, the plan.
    module procedure tensor_summary
        call unused(d)
        associate (res => self%res, rep => self%rep)
            s = ' tensor'
            if (res%fitted) then
                s = s//' I_principal = '//sci(res%moments(1), 5)//', '// &
                    sci(res%moments(2), 5)//', '//sci(res%moments(3), 5)//' (u '// &
                    sci(res%u_moments(1), 2)//', '//sci(res%u_moments(2), 2)//', '// &
                    sci(res%u_moments(3), 2)//'), chi2 '//fixed(res%chi2, 2)//'/dof '// &
                    itoa(res%dof)//', '//itoa(res%hangs)//' hangs, projection off by '// &
                    sci(res%projection_difference, 2)
                if (res%mc_samples > 0) s = s//', Monte Carlo u '// &
                    sci(res%u_moments_mc(1), 2)//', '//sci(res%u_moments_mc(2), 2)//', '// &
                    sci(res%u_moments_mc(3), 2)//' from '//itoa(res%mc_samples)// &
                    ' samples, '//fixed(rep%wall_seconds, 2)//' s'//ranks_note(rep)// &
                    resume_note(rep)
            end if
            if (res%plan > 0) then
                if (res%fitted) s = s//','
                s = s//' a plan of '//itoa(res%plan)//' hangs in '//res%plan_file
            end if
        end associate
        s = s//';'
    end procedure tensor_summary

    !> The task of its Monte Carlo on the other ranks of an MPI run (tensor_sweep_task).
    module procedure tensor_analysis_sweep_task
        call unused(self)
        call unused(sweep)
        call tensor_sweep_task(d, payload, task, stat)
    end procedure tensor_analysis_sweep_task

end submodule tensor_impl
