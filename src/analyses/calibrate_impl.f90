!> Analysis calibrate: how it works (see module calibrate).
!!
!! The parameters: the scale s of b b', the reference's moment I0 (a body of known moment:
!! stated as reference_I1 +- u_reference_I1; a test mass: the moment without it, free),
!! the test mass m_t (stated as test_mass +- u_test_mass), and delta_l.  Release k's
!! moment is I0 (+ m_t r_k^2 with a test mass at radius r_k); its periods are those of its
!! rig with l + delta_l, l' + delta_l, b sqrt(s), b' sqrt(s) (module rig_calibration), the
!! exact torsion period or the simulated one (period_inversion's rig_period_s).  A
!! residual per timed period, (T_model - T)/u_T, and one per stated quantity,
!! (p - stated)/u; a quantity stated with u = 0 is held.  The fit is tried first with
!! delta_l; when the estimator finds the Jacobian rank-deficient (the releases at one
!! length), or the two correlate beyond CORR_MAX, the note is kept and the fit repeated
!! with delta_l = 0.
submodule (calibrate) calibrate_impl
    use status, only: set_error, ERR_DECK, ERR_NUMERIC
    use text, only: itoa, sci, fixed, quoted, rshort
    use output_io, only: write_kv, all_finite
    use deck, only: deck_echo
    use deck_runs, only: rig_of, start_of, accuracy_of, deck_inputs
    use rig, only: rig_t, accuracy_t
    use estimator, only: lsq_problem_t, lsq_options_t, lsq_result_t, estimate
    use measurement, only: OBS_RECORD
    use measurement_read, only: read_releases
    use period_inversion, only: rig_period_s, is_torsion_rig, CYCLES_SIM_MAX
    use rig_calibration, only: calibrated_rig
    use crc64, only: crc64_of, hex16
    use version, only: BIFILAR_VERSION
    use certificate, only: certificate_t, cert_new, cert_section, cert_text, cert_table, &
        cert_row, cert_write, cert_note, cert_now, CELL
    implicit none

    !> Full parameter vector: delta_l, s, I0, m_t.
    integer, parameter :: Q_DL = 1, Q_S = 2, Q_I0 = 3, Q_MT = 4
    !> A correlation of delta_l and s beyond this: the data do not separate them (the
    !! amplitude's second-order effect is all that tells them apart at one length)
    real(dp), parameter :: CORR_MAX = 0.99_dp
    character(len=16), parameter :: Q_NAMES(4) = [character(len=16) :: 'delta_l', 'scale', &
        'I_reference', 'test_mass']

    type, extends(lsq_problem_t) :: calib_problem_t
        type(rig_t), allocatable :: rigs(:)     !! each period's release rig (taped)
        real(dp), allocatable :: per(:), amp(:), u(:), r2(:)    !! r2: test radius^2
        !> the cycles each period's time spans: on a rig whose periods are simulated, the
        !! model's mean period over as many cycles from the release (not its first one)
        real(dp), allocatable :: cyc(:)
        real(dp) :: q0(4) = 0.0_dp              !! the full parameters (held ones used)
        real(dp) :: stated(4) = 0.0_dp, u_stated(4) = 0.0_dp
        logical :: prior(4) = .false.           !! a residual for the stated value
        integer, allocatable :: act(:)          !! the active parameters
        type(accuracy_t) :: acc
    contains
        procedure :: residual => calib_residual
        procedure :: nres => calib_nres
    end type calib_problem_t

contains

    integer function calib_nres(prob)
        class(calib_problem_t), intent(in) :: prob
        calib_nres = size(prob%per) + count(prob%prior(prob%act))
    end function calib_nres

    subroutine calib_residual(prob, p, r, stat)
        class(calib_problem_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        real(dp) :: q(4), t
        type(rig_calibration_t) :: cal
        integer :: k, j, n
        stat%code = 0
        r = 0.0_dp
        q = prob%q0
        q(prob%act) = p
        if (.not. (q(Q_S) > 0.0_dp) .or. .not. (q(Q_I0) > 0.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'calibrate: scale or moment not positive')
            return
        end if
        cal%delta_l = q(Q_DL)
        cal%scale = q(Q_S)
        n = size(prob%per)
        do k = 1, n
            call rig_period_s(calibrated_rig(cal, prob%rigs(k)), prob%acc, &
                              q(Q_I0) + q(Q_MT)*prob%r2(k), prob%amp(k), t, stat, prob%cyc(k))
            if (stat%code /= 0) return
            r(k) = (t - prob%per(k))/prob%u(k)
        end do
        do j = 1, size(prob%act)
            if (.not. prob%prior(prob%act(j))) cycle
            n = n + 1
            r(n) = (p(j) - prob%stated(prob%act(j)))/prob%u_stated(prob%act(j))
        end do
    end subroutine calib_residual

    !> The reference's swings read as identify reads them; timed periods with their u.
    module procedure calibrate_ready
        integer :: i, nrel
        stat%code = 0
        if (len_trim(d%measurement%record) > 0 .or. d%measurement%monte_carlo > 0) then
            call set_error(stat, ERR_DECK, '&measurement record or monte_carlo with analyses '// &
                '= ''calibrate'': the calibration fits timed periods; allowed: periods or '// &
                'trials (a table of timed releases), monte_carlo = 0')
            return
        end if
        if (len_trim(d%measurement%calibration) > 0 .or. len_trim(d%measurement%tare) > 0) then
            call set_error(stat, ERR_DECK, '&measurement calibration or tare with analyses = '// &
                '''calibrate'': a calibration is made on the taped rig with the reference '// &
                'alone; allowed: neither key in a calibrate deck')
            return
        end if
        call read_releases(d%measurement, rig_of(d), start_of(d), d%suspension%cables, &
                           deck_inputs(d, .true.), self%m, stat)
        if (stat%code /= 0) return
        if (any(self%m%obs%kind == OBS_RECORD)) then
            call set_error(stat, ERR_DECK, '&measurement trials with records and analyses = '// &
                '''calibrate'': the calibration fits timed periods; allowed: timed releases')
            return
        end if
        nrel = size(self%m%releases)
        do i = 1, nrel
            if (any(.not. (self%m%u_periods_of(i) > 0.0_dp))) then
                call set_error(stat, ERR_DECK, '&measurement u_period = 0 with analyses = '// &
                    '''calibrate'': chi^2 needs each timing''s u; allowed: u_period > 0 (or '// &
                    'a table''s column u_period)')
                return
            end if
        end do
        if (d%calibration%by_test_mass() .and. d%calibration%n_radii /= nrel) then
            call set_error(stat, ERR_DECK, '&calibration test_radii: '// &
                itoa(d%calibration%n_radii)//' radii for '//itoa(nrel)//' releases; '// &
                'allowed: one radius per release of &measurement, in their order')
            return
        end if
    end procedure calibrate_ready

    module procedure calibrate_run
        type(calib_problem_t) :: prob
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: fit
        type(status_t) :: st1
        real(dp) :: q(4), corr
        integer :: i, k, n, j
        integer, allocatable :: ks(:)
        if (present(options)) continue
        stat%code = 0
        associate (m => self%m, c => d%calibration, res => self%res)
            ! the periods of every release, with their rigs and radii
            n = 0
            allocate (prob%rigs(0), prob%per(0), prob%amp(0), prob%u(0), prob%r2(0), &
                      prob%cyc(0))
            do i = 1, size(m%releases)
                ks = m%of_release(i)
                prob%rigs = [prob%rigs, (m%releases(i)%rig, k=1, size(ks))]
                prob%per = [prob%per, m%periods_of(i)]
                prob%amp = [prob%amp, m%amplitudes_of(i)]
                prob%u = [prob%u, m%u_periods_of(i)]
                prob%cyc = [prob%cyc, m%cycles_of(i)]
                if (.not. is_torsion_rig(m%releases(i)%rig) .and. &
                    any(m%cycles_of(i) > CYCLES_SIM_MAX + 0.5_dp)) then
                    call set_error(stat, ERR_DECK, '&measurement cycles: release '//itoa(i)// &
                        ' is timed over '//rshort(maxval(m%cycles_of(i)))//' cycles on a '// &
                        'rig that is not symmetric (its periods are simulated from the '// &
                        'release, cycle by cycle, as they were timed); allowed: totals of '// &
                        'at most '//itoa(CYCLES_SIM_MAX)//' cycles on such a rig')
                    return
                end if
                if (c%by_test_mass()) then
                    prob%r2 = [prob%r2, (c%test_radii(i)**2, k=1, size(ks))]
                else
                    prob%r2 = [prob%r2, (0.0_dp, k=1, size(ks))]
                end if
            end do
            prob%acc = accuracy_of(d)
            res%n_periods = size(prob%per)
            res%n_releases = size(m%releases)
            ! the parameters: their start, what is stated of them
            prob%q0 = [0.0_dp, 1.0_dp, d%body%inertia(1), 0.0_dp]
            if (c%by_test_mass()) then
                prob%q0(Q_MT) = c%test_mass
                prob%stated(Q_MT) = c%test_mass
                prob%u_stated(Q_MT) = c%u_test_mass
                prob%prior(Q_MT) = c%u_test_mass > 0.0_dp
            else
                prob%q0(Q_I0) = c%reference_i1
                prob%stated(Q_I0) = c%reference_i1
                prob%u_stated(Q_I0) = c%u_reference_i1
                prob%prior(Q_I0) = c%u_reference_i1 > 0.0_dp
            end if
            ! active: delta_l (first try), s, I0 unless held, m_t when stated with u
            prob%act = [Q_DL, Q_S]
            if (c%by_test_mass() .or. prob%prior(Q_I0)) prob%act = [prob%act, Q_I0]
            if (prob%prior(Q_MT)) prob%act = [prob%act, Q_MT]
            opts%covariance = .true.
            opts%u_stated = .true.
            opts%names = Q_NAMES(prob%act)
            opts%h = 1.0e-6_dp*max(abs(prob%q0(prob%act)), [d%suspension%l, &
                (1.0_dp, j=2, size(prob%act))])
            res%not_separable = ''
            call estimate(prob, prob%q0(prob%act), opts, fit, st1)
            corr = 1.0_dp
            if (st1%code == 0 .and. allocated(fit%cov_fit)) &
                corr = fit%cov_fit(1, 2)/sqrt(fit%cov_fit(1, 1)*fit%cov_fit(2, 2))
            if (st1%code /= 0 .or. .not. allocated(fit%cov) .or. abs(corr) > CORR_MAX) then
                if (allocated(fit%note)) res%not_separable = fit%note
                if (len(res%not_separable) == 0) res%not_separable = 'delta_l and scale '// &
                    '(correlation '//fixed(corr, 5)//')'
                prob%act = prob%act(2:)
                opts%names = Q_NAMES(prob%act)
                opts%h = opts%h(2:)
                call estimate(prob, prob%q0(prob%act), opts, fit, stat)
                if (stat%code /= 0) return
                if (.not. allocated(fit%cov)) then
                    call set_error(stat, ERR_NUMERIC, 'calibrate: the reference''s periods '// &
                        'do not determine the scale of b b'' ('//fit%note//')')
                    return
                end if
            end if
            q = prob%q0
            q(prob%act) = fit%p
            res%cal%separable = prob%act(1) == Q_DL
            res%cal%delta_l = q(Q_DL)
            res%cal%scale = q(Q_S)
            res%cal%cov = 0.0_dp
            do i = 1, size(prob%act)
                do j = 1, size(prob%act)
                    if (prob%act(i) <= Q_S .and. prob%act(j) <= Q_S) &
                        res%cal%cov(prob%act(i), prob%act(j)) = fit%cov_fit(i, j)
                end do
            end do
            res%cal%l = d%suspension%l
            res%cal%b = d%suspension%b
            res%cal%b_prime = d%suspension%b_prime
            res%cal%chi2 = fit%cost
            res%cal%dof = fit%dof
            res%i_reference = q(Q_I0)
            res%u_i_reference = 0.0_dp
            res%test_mass = q(Q_MT)
            res%u_test_mass = 0.0_dp
            do i = 1, size(prob%act)
                if (prob%act(i) == Q_I0) res%u_i_reference = sqrt(fit%cov_fit(i, i))
                if (prob%act(i) == Q_MT) res%u_test_mass = sqrt(fit%cov_fit(i, i))
            end do
            res%p_value = fit%p_value
            res%birge = fit%birge
            res%consistent = fit%consistent
            if (.not. fit%consistent) call self%add_warning('calibrate: the reference''s '// &
                'periods disagree with the model beyond their u (chi^2 = '// &
                sci(fit%cost, 3)//' on '//itoa(fit%dof)//' dof, p = '//sci(fit%p_value, 2)// &
                '): the covariance is inflated by the Birge ratio '//fixed(fit%birge, 2))
        end associate
        call write_calibration(d, outdir, self%res, files, stat)
        if (stat%code /= 0) return
        call write_calibration_certificate(d, outdir, self%res, files, stat)
    end procedure calibrate_run

    module procedure calibrate_summary
        s = ' calibrate scale = '//trim(sci(self%res%cal%scale, 6))//' ± '// &
            trim(sci(sqrt(self%res%cal%cov(2, 2)), 2))
        if (self%res%cal%separable) s = s//', delta_l = '//trim(sci(self%res%cal%delta_l, 3))
        if (len(d%name) < 0) s = s//''
        s = s//';'
    end procedure calibrate_summary

    !> OUTDIR/NAME.calibration: the constants, their covariance, the fit's check.
    subroutine write_calibration(d, outdir, res, files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(calibrate_result_t), intent(in) :: res
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        integer :: u, ios
        real(dp) :: corr
        associate (cal => res%cal)
            if (.not. all_finite([cal%delta_l, cal%scale, reshape(cal%cov, [4]), cal%chi2, &
                                  res%i_reference, res%u_i_reference])) then
                call set_error(stat, ERR_NUMERIC, 'calibrate: a result is not finite')
                return
            end if
            call files%open(outdir//'/'//d%name//'.calibration', u, stat)
            if (stat%code /= 0) return
            ios = 0
            write (u, '(a)', iostat=ios) '# bifilar calibrate: '//trim(d%scene%title)
            if (ios == 0) write (u, '(a)', iostat=ios) '# the rig''s effective constants: '// &
                'l -> l + delta_l, b b'' -> scale b b'' (R R'' on a platform); a measuring '// &
                'deck takes them with &measurement calibration = ''FILE'''
            call deck_echo(d, u, ios)
            call write_kv(u, 'delta_l', cal%delta_l, ios)
            call write_kv(u, 'u_delta_l', sqrt(cal%cov(1, 1)), ios)
            call write_kv(u, 'scale', cal%scale, ios)
            call write_kv(u, 'u_scale', sqrt(cal%cov(2, 2)), ios)
            call write_kv(u, 'var_delta_l', cal%cov(1, 1), ios)
            call write_kv(u, 'var_scale', cal%cov(2, 2), ios)
            call write_kv(u, 'cov_delta_l_scale', cal%cov(1, 2), ios)
            corr = 0.0_dp
            if (cal%cov(1, 1) > 0.0_dp .and. cal%cov(2, 2) > 0.0_dp) &
                corr = cal%cov(1, 2)/sqrt(cal%cov(1, 1)*cal%cov(2, 2))
            call write_kv(u, 'correlation', corr, ios)
            call write_kv(u, 'delta_l_estimated', merge(1, 0, cal%separable), ios)
            call write_kv(u, 'not_separable', quoted(res%not_separable), ios)
            call write_kv(u, 'l', cal%l, ios)
            call write_kv(u, 'b', cal%b, ios)
            call write_kv(u, 'b_prime', cal%b_prime, ios)
            call write_kv(u, 'I_reference', res%i_reference, ios)
            call write_kv(u, 'u_I_reference', res%u_i_reference, ios)
            if (d%calibration%by_test_mass()) then
                call write_kv(u, 'test_mass', res%test_mass, ios)
                call write_kv(u, 'u_test_mass', res%u_test_mass, ios)
            end if
            call write_kv(u, 'chi2', cal%chi2, ios)
            call write_kv(u, 'dof', cal%dof, ios)
            call write_kv(u, 'p_value', res%p_value, ios)
            call write_kv(u, 'consistent', res%consistent, ios)
            call write_kv(u, 'releases', res%n_releases, ios)
            call write_kv(u, 'periods', res%n_periods, ios)
            call files%close(u, ios, stat)
        end associate
    end subroutine write_calibration

    !> OUTDIR/NAME.certificate.html: the calibration's certificate (module certificate).
    subroutine write_calibration_certificate(d, outdir, res, files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(calibrate_result_t), intent(in) :: res
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        type(certificate_t) :: c
        character(len=:), allocatable :: crc
        crc = '(none)'
        if (allocated(d%text)) crc = hex16(crc64_of(d%text))
        c = cert_new('Calibration of a pendulum rig with a reference', trim(d%scene%title), &
                     BIFILAR_VERSION, d%path, crc)
        associate (cal => res%cal)
            call cert_section(c, 'Result')
            call cert_text(c, 'The rig''s effective constants: the cable length l + delta_l '// &
                'and the spacing product scale x b b'' (R R'' on a platform), with their '// &
                'standard uncertainties and correlation; k = 2 gives about 95 % coverage.')
            call cert_table(c, 'constant'//CELL//'value'//CELL//'standard u')
            call cert_row(c, 'scale of b b'''//CELL//trim(sci(cal%scale, 7))//CELL// &
                          trim(sci(sqrt(cal%cov(2, 2)), 3)))
            if (cal%separable) then
                call cert_row(c, 'delta_l'//CELL//trim(sci(cal%delta_l, 5))//CELL// &
                              trim(sci(sqrt(cal%cov(1, 1)), 3)))
            else
                call cert_note(c, 'The data cannot separate '//res%not_separable//': the '// &
                    'releases were made at one cable length, where the period depends on '// &
                    'b b'' / l alone.  delta_l is held at 0 and the scale carries both; the '// &
                    'calibration serves decks at that length.')
            end if
            call cert_section(c, 'Reference and rig as measured')
            call cert_table(c, 'quantity'//CELL//'value'//CELL//'standard u')
            if (d%calibration%by_test_mass()) then
                call cert_row(c, 'test mass (stated)'//CELL//trim(sci(d%calibration%test_mass, &
                              6))//CELL//trim(sci(d%calibration%u_test_mass, 3)))
                call cert_row(c, 'I1 without the test mass (fitted)'//CELL// &
                              trim(sci(res%i_reference, 6))//CELL// &
                              trim(sci(res%u_i_reference, 3)))
            else
                call cert_row(c, 'reference I1 (stated)'//CELL// &
                              trim(sci(d%calibration%reference_i1, 6))//CELL// &
                              trim(sci(d%calibration%u_reference_i1, 3)))
            end if
            call cert_row(c, 'l (taped)'//CELL//trim(sci(cal%l, 6))//CELL// &
                          trim(sci(d%measurement%u_l, 3)))
            call cert_row(c, 'b (taped)'//CELL//trim(sci(cal%b, 6))//CELL// &
                          trim(sci(d%measurement%u_b, 3)))
            call cert_row(c, 'b'' (taped)'//CELL//trim(sci(cal%b_prime, 6))//CELL// &
                          trim(sci(d%measurement%u_b_prime, 3)))
            call cert_row(c, 'mass'//CELL//trim(sci(d%body%mass, 6))//CELL// &
                          trim(sci(d%measurement%u_mass, 3)))
            call cert_section(c, 'Method and model')
            call cert_text(c, itoa(res%n_periods)//' timed periods of '// &
                itoa(res%n_releases)//' release(s), each against the period of the rig '// &
                'with the calibrated constants (the exact period of torsion, or the '// &
                'simulated one on an asymmetric rig), fitted by weighted least squares '// &
                'with the reference''s statement as one more residual.')
            call cert_section(c, 'Checks')
            call cert_table(c, 'check'//CELL//'value')
            call cert_row(c, 'chi^2 (dof)'//CELL//trim(sci(cal%chi2, 4))//' ('// &
                          itoa(cal%dof)//')')
            call cert_row(c, 'p-value'//CELL//trim(sci(res%p_value, 3)))
            call cert_row(c, 'consistent'//CELL//trim(merge('yes', 'no ', res%consistent)))
        end associate
        call cert_write(c, outdir//'/'//d%name//'.certificate.html', cert_now(), files, stat)
    end subroutine write_calibration_certificate


end submodule calibrate_impl
