!> The implementation of analysis identify (submodule of identify): the preconditions,
!! the periods' and the record's analyses, their Monte Carlo, and the output files.
submodule (identify) identify_impl
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: pi
    use status, only: set_error, STATUS_OK, ERR_DECK, ERR_NUMERIC, ERR_IO
    use text, only: itoa, sci, count_words
    use deck, only: deck_echo, estimated, TAU_END_MAX
    use output_io, only: write_kv, all_finite
    use fast_format, only: es_field
    use geometry, only: pendulum_t
    use bifilar_model, only: NSTATE
    use rig, only: rig_t, accuracy_t, rig_of, start_of, accuracy_of, make_pendulum, start_state
    use least_squares, only: lsq_result_t, lsq_jacobian
    use budget, only: input_u_t
    use records, only: read_record, record_file, mean_period
    use record_fit, only: record_fit_t, record_mc_task_t, fit_problem, fit_record, covariance, &
        input_sensitivity, budget_inputs, record_mc_task, explain_fit_failure, PARAM_NAMES
    use period_inversion, only: period_fit_t, invert_periods, period_budget, &
                                period_monte_carlo, linear_inertia, is_torsion_rig, &
                                period_mc_task, period_mc_task_t
    use crc64, only: file_crc, crc_parts, crc_join
    use monte_carlo, only: monte_carlo_run
    implicit none

contains

    !> The preconditions of analyses = 'identify', checked before any computing: the
    !! paper's model; periods or a record, not both; with periods only I1 estimated and the
    !! periods possible on a symmetric rig (T(I1 -> 0) below each); with a record, the
    !! record readable and sound (read_record), I1 among the estimated parameters,
    !! 'amplitude' only with &start mode 'raised', more samples than parameters, the start.
    module procedure identify_ready
        type(pendulum_t) :: p
        type(record_t) :: rec
        type(period_fit_t) :: f
        real(dp) :: y0(NSTATE), th0(5), t_max
        integer :: np
        stat%code = 0
        if (trim(d%model) /= 'kane') then
            call set_error(stat, ERR_DECK, 'analyses = ''identify'': &scene model = '''// &
                trim(d%model)//''': identify fits the paper''s model; allowed: model = ''kane''')
            return
        end if
        if (d%n_periods > 0 .eqv. len_trim(d%record) > 0) then
            call set_error(stat, ERR_DECK, 'analyses = ''identify'': &measurement needs '// &
                'either periods (with amplitudes) or a record, and not both; allowed: '// &
                'periods = 1.52, 1.55, amplitudes = 10, 30 or record = ''swing.dat''')
            return
        end if
        call make_pendulum(rig_of(d), p, stat)
        if (stat%code /= 0) return
        if (.not. estimated(d, 'I1')) then
            call set_error(stat, ERR_DECK, '&measurement estimate = '''//trim(d%estimate)// &
                ''': I1 is what identify estimates; allowed: ''I1'' followed by any of '// &
                'c_v, c_q, amplitude, t0 (with a record)')
            return
        end if
        if (d%n_periods > 0) then
            if (count_words(d%estimate) /= 1) then
                call set_error(stat, ERR_DECK, '&measurement estimate = '''// &
                    trim(d%estimate)//''': with periods only I1 is estimated; allowed: '// &
                    '''I1'' (c_v, c_q, amplitude, t0 need a record)')
                return
            end if
            if (is_torsion_rig(rig_of(d))) then
                ! a period no positive I1 gives: refused now (cheap on a symmetric rig)
                call invert_periods(rig_of(d), accuracy_of(d), d%periods(1:d%n_periods), &
                                    d%amplitudes(1:d%n_periods), &
                                    input_u(d), f, stat)
                if (stat%code == ERR_DECK) return
                stat%code = 0
            end if
            return
        end if
        call read_record(d, rec, stat)
        if (stat%code /= 0) return
        ! the model runs from the release (t = 0) to the last sample: no longer than a
        ! simulation may run (a record of huge times would run the integrator for ever)
        t_max = TAU_END_MAX/sqrt(d%g/d%b_prime)
        if (rec%t(size(rec%t)) > t_max) then
            call set_error(stat, ERR_DECK, '&measurement record = '''//trim(d%record)// &
                ''': its last sample, t = '//sci(rec%t(size(rec%t)))//' s after the '// &
                'release, is beyond what the model runs; allowed: times up to '//sci(t_max)// &
                ' s (tau = t sqrt(g/b_prime) <= '//sci(TAU_END_MAX)//', as &integration '// &
                'tau_end)')
            return
        end if
        ! a record that ends within a thousandth of the time scale (b_prime/g)^(1/2) of the
        ! release holds the release alone: nothing to identify, and steps at roundoff
        if (rec%t(size(rec%t)) < 1.0e-3_dp*t_max/TAU_END_MAX) then
            call set_error(stat, ERR_DECK, '&measurement record = '''//trim(d%record)// &
                ''': its last sample, t = '//sci(rec%t(size(rec%t)))//' s after the '// &
                'release, is too early to show a swing; allowed: times up to at least '// &
                sci(1.0e-3_dp*t_max/TAU_END_MAX)//' s (tau = t sqrt(g/b_prime) >= 1e-3)')
            return
        end if
        if (estimated(d, 'amplitude') .and. trim(d%mode) /= 'raised') then
            call set_error(stat, ERR_DECK, '&measurement estimate = '''//trim(d%estimate)// &
                ''': amplitude is the raised start''s; allowed with &start mode = ''raised''')
            return
        end if
        np = count_words(d%estimate)
        if (size(rec%t) <= np) then
            call set_error(stat, ERR_DECK, '&measurement record = '''//trim(d%record)// &
                ''': '//itoa(size(rec%t))//' samples for '//itoa(np)//' parameters; '// &
                'allowed: more samples than parameters')
            return
        end if
        call start_state(start_of(d), p, y0, th0, stat)
    end procedure identify_ready

    !> Run analyses = 'identify' for a deck and write OUTDIR/NAME.identify (and, with a
    !! record, OUTDIR/NAME.fit.dat) into `files`.  The Monte Carlo is a sweep over the ranks
    !! and threads, checkpointed to OUTDIR/NAME.identify_mc.partial (options: --resume and
    !! the interval; report: how its sweep went, ranks 1 without Monte Carlo).
    module procedure run_identify
        real(dp) :: c0, c1
        type(record_t) :: rec
        type(sweep_report_t) :: rep
        call cpu_time(c0)
        rep%note = ''
        if (d%n_periods > 0) then
            call identify_periods(d, res, stat, outdir, options, rep, files)
        else
            call read_record(d, rec, stat)
            if (stat%code == 0) call identify_record(d, rec, res, stat, outdir, options, rep, &
                                                     files)
        end if
        if (present(report)) report = rep
        call cpu_time(c1)
        res%cpu_seconds = c1 - c0
        if (stat%code /= 0) return
        call write_identify(d, outdir, res, files, stat)
        if (stat%code /= 0) return
        if (res%from_record) call write_fit(d, outdir, rec, res, files, stat)
    end procedure run_identify

    !> The standard uncertainties of a deck's inputs.
    pure function input_u(d) result(u)
        type(deck_t), intent(in) :: d
        type(input_u_t) :: u
        u = input_u_t(mass=d%u_mass, l=d%u_l, l_prime=d%u_l_prime, b=d%u_b, &
                      b_prime=d%u_b_prime, g=d%u_g, period=d%u_period, amplitude=d%u_amplitude)
    end function input_u

    !> I1 from the deck's periods (module period_inversion); the Monte Carlo's sweep
    !! checkpointed in outdir when given (see run_identify).
    subroutine identify_periods(d, res, stat, outdir, options, report, files)
        type(deck_t), intent(in) :: d
        type(identify_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        character(len=*), intent(in), optional :: outdir
        type(sweep_options_t), intent(in), optional :: options
        type(sweep_report_t), intent(inout), optional :: report
        type(out_files_t), intent(in), optional :: files
        type(period_fit_t) :: f
        type(input_u_t) :: u
        real(dp) :: mean, sdev
        integer :: n, imin
        type(rig_t) :: rg
        type(accuracy_t) :: acc
        n = d%n_periods
        u = input_u(d)
        rg = rig_of(d)
        acc = accuracy_of(d)
        associate (per => d%periods(1:n), amps => d%amplitudes(1:n))
            call invert_periods(rg, acc, per, amps, u, f, stat)
            if (stat%code /= 0) return
            if (u%period == 0.0_dp .and. n >= 2) then
                ! no stated timing uncertainty: the periods' scatter about the model is it
                ! (s^2 = sum of squares over n - 1), and the inversion is weighted with it
                res%u_period_scatter = sqrt(sum((f%model_periods - per)**2)/(n - 1))
                u%period = res%u_period_scatter
                if (u%period > 0.0_dp) call invert_periods(rg, acc, per, amps, u, f, stat)
                if (stat%code /= 0) return
            end if
            call period_budget(rg, acc, per, amps, u, f, stat)
            if (stat%code /= 0) return
            if (d%monte_carlo > 0) then
                call period_monte_carlo(d, per, amps, u, f%i1, d%monte_carlo, &
                                        d%seed, mean, sdev, stat, outdir, options, report, &
                                        files)
                if (stat%code /= 0) return
                res%u_i1_mc = sdev
                res%mc_mean = mean
            end if
            imin = minloc(amps, 1)
            res%period_linear = per(imin)
        end associate
        res%from_record = .false.
        res%periods_exact = is_torsion_rig(rg)
        res%i1 = f%i1
        res%u_i1 = f%u_i1
        res%residual_rms = f%residual_rms
        res%iterations = f%iterations
        res%samples = n
        res%np = 1
        res%names(1) = 'I1'
        res%p(1) = f%i1
        res%u_p(1) = f%u_i1
        res%model_periods = f%model_periods
        res%budget = f%budget
        res%i1_linear = linear_inertia(rg, res%period_linear)
        res%linear_error = res%i1_linear/res%i1 - 1.0_dp
    end subroutine identify_periods

    !> I1 (and the other parameters asked for) from a record: the fit, the first-order
    !! budget, Monte Carlo when asked (its sweep checkpointed in outdir when given, see
    !! run_identify).
    module procedure identify_record
        type(record_fit_t) :: prob
        type(lsq_result_t) :: fit
        real(dp), allocatable :: p0(:), h(:), jac(:, :), cov(:, :), dpdx(:, :), ux(:), xval(:)
        character(len=16), allocatable :: xname(:)
        real(dp) :: s2
        integer :: m, np, j, nx
        m = size(rec%t)
        call fit_problem(d, rec, prob, p0, h)
        np = prob%np
        call fit_record(prob, p0, h, fit, stat)
        res%iterations = fit%iterations
        res%evaluations = fit%evaluations
        if (stat%code == ERR_NUMERIC) then
            call explain_fit_failure(stat, prob, fit)
            return
        else if (stat%code /= 0) then
            stat%msg = 'identify: the model at the start values: '//stat%msg
            return
        end if
        ! the Jacobian at the estimate by central differences, the covariance
        allocate (jac(m, np))
        call lsq_jacobian(prob, fit%p, fit%r, h, jac, stat, central=.true.)
        res%evaluations = res%evaluations + 2*np
        if (stat%code /= 0) then
            stat%msg = 'identify: the Jacobian at the estimate: '//stat%msg
            return
        end if
        if (rec%has_u) then
            s2 = 1.0_dp
        else
            s2 = fit%cost/(m - np)
        end if
        call covariance(jac, s2, cov, stat)
        if (stat%code /= 0) then
            call explain_fit_failure(stat, prob, fit)
            return
        end if
        call budget_inputs(d, xname, xval, ux)
        nx = size(xval)
        allocate (dpdx(np, nx))
        do j = 1, nx
            call input_sensitivity(prob, fit%p, jac, j, xval(j), dpdx(:, j), stat)
            res%evaluations = res%evaluations + 2
            if (stat%code /= 0) then
                stat%msg = 'identify: sensitivity to '//trim(xname(j))//': '//stat%msg
                return
            end if
        end do
        res%from_record = .true.
        res%np = np
        res%samples = m
        res%sigma = sqrt(s2)
        res%sigma_stated = rec%has_u
        do j = 1, np
            res%names(j) = PARAM_NAMES(prob%which(j))
            res%p(j) = fit%p(j)
            res%u_p(j) = sqrt(cov(j, j) + sum((dpdx(j, :)*ux)**2))
        end do
        res%i1 = res%p(1)
        res%u_i1 = res%u_p(1)
        res%u_i1_fit = sqrt(cov(1, 1))
        allocate (res%budget(nx + 1))
        res%budget(1) = budget_row_t('record', sqrt(s2), sqrt(s2), res%u_i1_fit/sqrt(s2), &
                                     res%u_i1_fit)
        do j = 1, nx
            res%budget(j + 1) = budget_row_t(xname(j), xval(j), ux(j), dpdx(1, j), &
                                             abs(dpdx(1, j))*ux(j))
        end do
        res%residual_rms = sqrt(sum((fit%r/prob%w)**2)/m)
        allocate (res%model(m))
        res%model = fit%r/prob%w + rec%v
        if (d%monte_carlo > 0) then
            call record_monte_carlo(d, rec, fit%p, jac, res, stat, outdir, options, report, &
                                    files)
            if (stat%code /= 0) return
        end if
        res%period_linear = mean_period(rec)
        if (res%period_linear > 0.0_dp) then
            res%i1_linear = linear_inertia(rig_of(d), res%period_linear)
            res%linear_error = res%i1_linear/res%i1 - 1.0_dp
        end if
    end procedure identify_record

    !> Monte Carlo of a record fit (see the module header) as a sweep (module monte_carlo):
    !! res%u_i1_mc, res%mc_mean.  phat, jac: the estimate and its Jacobian, res%u_p and
    !! res%sigma its first-order u and s; the payload carries them (and the record's
    !! CRC-64) to the other ranks.
    subroutine record_monte_carlo(d, rec, phat, jac, res, stat, outdir, options, report, files)
        type(deck_t), intent(in) :: d
        type(record_t), intent(in) :: rec
        real(dp), intent(in) :: phat(:), jac(:, :)
        type(identify_result_t), intent(inout) :: res
        type(status_t), intent(out) :: stat
        character(len=*), intent(in), optional :: outdir
        type(sweep_options_t), intent(in), optional :: options
        type(sweep_report_t), intent(inout), optional :: report
        type(out_files_t), intent(in), optional :: files
        type(record_mc_task_t) :: task
        real(dp), allocatable :: payload(:), mean(:), sdev(:)
        integer(int64) :: crc
        integer :: np
        np = size(phat)
        call file_crc(record_file(d), crc, stat)
        if (stat%code /= 0) return
        payload = [crc_parts(crc), res%sigma, real(np, dp), phat, res%u_p(1:np), &
                   reshape(jac, [size(jac)])]
        call record_mc_task(d, rec, payload, task)
        allocate (mean(np), sdev(np))
        call monte_carlo_run(task, d, d%monte_carlo, payload, mean, sdev, stat, outdir, &
                             options, report, files)
        if (stat%code /= 0) return
        res%mc_mean = mean(1)
        res%u_i1_mc = sdev(1)
    end subroutine record_monte_carlo

    !> The task of identify's Monte Carlo (sweep 'identify_mc') as the other ranks of an MPI
    !! run build it: from the deck (its periods, or its record, read here and checked
    !! against rank 0's by its CRC-64) and the sweep's payload.  ERR_DECK when the record
    !! cannot be read or is another than rank 0's.
    module procedure identify_mc_task
        type(record_t) :: rec
        integer(int64) :: crc
        stat%code = 0
        if (d%n_periods > 0) then
            allocate (period_mc_task_t :: task)
            select type (task)
            type is (period_mc_task_t)
                call period_mc_task(d, payload, task)
            end select
            return
        end if
        call read_record(d, rec, stat)
        if (stat%code == 0) call file_crc(record_file(d), crc, stat)
        if (stat%code /= 0) return
        if (crc /= crc_join(payload(1:2))) then
            call set_error(stat, ERR_DECK, '&measurement record = '''//trim(d%record)// &
                ''': reads another record at '//record_file(d)//' than rank 0 (its CRC-64 '// &
                'differs): every rank must see the same file')
            return
        end if
        allocate (record_mc_task_t :: task)
        select type (task)
        type is (record_mc_task_t)
            call record_mc_task(d, rec, payload, task)
        end select
    end procedure identify_mc_task

    !> OUTDIR/NAME.identify: key = value lines, then the budget table of I1.
    subroutine write_identify(d, outdir, res, files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(identify_result_t), intent(in) :: res
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        integer :: u, ios, j
        character(len=24) :: f(4)
        if (.not. all_finite([res%i1, res%u_i1, res%i1_linear, res%linear_error, &
                              res%residual_rms, res%p, res%u_p, res%u_i1_mc, &
                              res%budget%value, res%budget%u, res%budget%sensitivity])) then
            call set_error(stat, ERR_NUMERIC, 'identify: a result is not finite')
            return
        end if
        call files%open(outdir//'/'//d%name//'.identify', u, stat)
        if (stat%code /= 0) return
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar identify: '//trim(d%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# I1 and its standard uncertainties in the '// &
            'deck''s units (mass x length^2); c_v, c_q in torque per rate (squared), '// &
            'amplitude in degrees, t0 in s'
        call deck_echo(d, u, ios)
        call write_kv(u, 'I1', res%i1, ios)
        call write_kv(u, 'u_I1', res%u_i1, ios)
        if (d%monte_carlo > 0) call write_kv(u, 'u_I1_monte_carlo', res%u_i1_mc, ios)
        call write_kv(u, 'I1_linear', res%i1_linear, ios)
        call write_kv(u, 'linear_error', res%linear_error, ios)
        do j = 2, res%np
            call write_kv(u, trim(res%names(j)), res%p(j), ios)
            call write_kv(u, 'u_'//trim(res%names(j)), res%u_p(j), ios)
        end do
        call write_kv(u, 'residual_rms', res%residual_rms, ios)
        call write_kv(u, 'iterations', res%iterations, ios)
        call write_kv(u, 'cpu_seconds', res%cpu_seconds, ios)
        if (res%from_record) then
            call write_kv(u, 'mode', 'record', ios)
            call write_kv(u, 'quantity', trim(d%quantity), ios)
            call write_kv(u, 'samples', res%samples, ios)
            call write_kv(u, 'sigma', res%sigma, ios)
            call write_kv(u, 'sigma_source', trim(merge('stated   ', 'residuals', &
                                                        res%sigma_stated)), ios)
            call write_kv(u, 'u_I1_fit', res%u_i1_fit, ios)
            call write_kv(u, 'model_evaluations', res%evaluations, ios)
            call write_kv(u, 'mean_period', res%period_linear, ios)
        else
            call write_kv(u, 'mode', 'periods', ios)
            call write_kv(u, 'period_model', trim(merge('exact torsion', 'simulated    ', &
                                                        res%periods_exact)), ios)
            do j = 1, res%samples
                call write_kv(u, 'model_period('//itoa(j)//')', res%model_periods(j), ios)
            end do
            call write_kv(u, 'linear_period', res%period_linear, ios)
            if (res%u_period_scatter >= 0.0_dp) &
                call write_kv(u, 'u_period_from_scatter', res%u_period_scatter, ios)
        end if
        if (d%monte_carlo > 0) then
            call write_kv(u, 'monte_carlo_samples', d%monte_carlo, ios)
            call write_kv(u, 'monte_carlo_seed', d%seed, ios)
            call write_kv(u, 'I1_monte_carlo_mean', res%mc_mean, ios)
        end if
        if (ios == 0) write (u, '(a)', iostat=ios) '# budget of I1 (first order, GUM): input '// &
            'value u sensitivity contribution (contribution = |sensitivity| u; u_I1 is '// &
            'their root sum of squares)'
        do j = 1, size(res%budget)
            call es_field(res%budget(j)%value, 15, f(1))
            call es_field(res%budget(j)%u, 15, f(2))
            call es_field(res%budget(j)%sensitivity, 15, f(3))
            call es_field(res%budget(j)%contribution, 15, f(4))
            if (ios == 0) write (u, '(a)', iostat=ios) res%budget(j)%input(1:14)//f(1)//f(2)// &
                f(3)//f(4)
        end do
        call files%close(u, ios, stat)
    end subroutine write_identify

    !> OUTDIR/NAME.fit.dat: t measured model residual (the record's units).
    subroutine write_fit(d, outdir, rec, res, files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(record_t), intent(in) :: rec
        type(identify_result_t), intent(in) :: res
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        integer :: u, ios, i
        character(len=96) :: row
        character(len=:), allocatable :: unit_name
        call files%open(outdir//'/'//d%name//'.fit.dat', u, stat)
        if (stat%code /= 0) return
        unit_name = trim(merge('theta4 (rad)', 'W (rad/s)   ', trim(d%quantity) == 'angle'))
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar identify fit: '//trim(d%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# t in s from release; measured, model '// &
            'and residual (measured - model) are '//unit_name
        call deck_echo(d, u, ios)
        if (ios == 0) write (u, '(a)', iostat=ios) '# t measured model residual'
        do i = 1, size(rec%t)
            call es_field(rec%t(i), 15, row(1:24))
            call es_field(rec%v(i), 15, row(25:48))
            call es_field(res%model(i), 15, row(49:72))
            call es_field(rec%v(i) - res%model(i), 15, row(73:96))
            if (ios == 0) write (u, '(a)', iostat=ios) row
        end do
        call files%close(u, ios, stat)
    end subroutine write_fit

end submodule identify_impl
