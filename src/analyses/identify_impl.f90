!> The implementation of analysis identify (submodule of identify): the preconditions, each
!! release's analysis (periods or a record), their pooling, the corrections and the checks
!! against what no body can give, the Monte Carlo, and the output files.
submodule (identify) identify_impl
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: pi
    use status, only: set_error, STATUS_OK, ERR_DECK, ERR_NUMERIC, ERR_MODEL
    use text, only: itoa, sci, fixed, count_words, quoted, rshort
    use deck, only: deck_echo, TAU_END_MAX
    use output_io, only: write_kv, all_finite
    use fast_format, only: es_field
    use geometry, only: pendulum_t
    use bifilar_model, only: NSTATE
    use platform_measure, only: offaxis_platform
    use rig, only: rig_t, start_t, accuracy_t, make_pendulum, start_state
    use deck_runs, only: rig_of, start_of, accuracy_of, deck_inputs, record_format_of, &
        record_file
    use estimator, only: lsq_result_t, lsq_jacobian, estimate, lsq_options_t, lsq_covariance, &
        LOSS_SQUARES, LOSS_HUBER
    use budget, only: input_u_t, ROW_INPUT, ROW_TIMING, ROW_AMPLITUDE, ROW_FIT, ROW_RELEASE, &
        ROW_TARE, ROW_ADDED, ROW_SESSION, ROW_AMPLITUDE_SCALE
    use records, only: read_record_file, record_format_t, mean_period, clean_mean_period, &
        u_column_warning, chosen_axis_note, record_t, MIN_SAMPLES
    use progress, only: say_note
    use measure_groups, only: measurement_group_t
    use measurement, only: release_t, observation_t, OBS_RECORD, OBS_TIMING, RIG_COLUMNS
    use measurement_read, only: read_releases, release_inputs
    use rig_calibration, only: rig_calibration_t, calibrate_measurement, calibration_row, &
        read_calibration_file
    use inputs, only: input_t, set_input
    use pooling, only: pooled_t, pool_releases, sessions_pooled_t, pool_sessions
    use stats, only: coverage_factor, welch_satterthwaite, NU_INFINITE, chi2_sf
    use model_follow, only: follows_record, not_following_message
    use tip_check, only: check_not_tipping
    use record_fit, only: record_fit_t, record_mc_task_t, fit_problem, fit_record, carry_inputs, &
        input_sensitivities, record_mc_task, explain_fit_failure, estimated_names, &
        correlation_time, fresh_jacobian, check_record_kind, PARAM_NAMES, P_BIAS, &
        determines_t, record_determines, stacked_weights, stacked_values, P_I2, P_I3, P_CG, &
        P_TILT, P_SWAY, find_release, record_start_t
    use period_inversion, only: period_fit_t, invert_periods, period_budget, &
                                period_monte_carlo, linear_inertia, is_torsion_rig, &
                                period_mc_task, period_mc_task_t, rig_period_s, &
                                torsion_period_s, simulated_period_s
    use crc64, only: crc64_of, crc_parts, hex16
    use monte_carlo, only: monte_carlo_run
    use work_estimate, only: check_timings, check_record_times, periods_runs, record_runs, &
        work_note, reference_periods, record_swing_period, check_fitted_amplitude, &
        CAUSES_HIGH, CAUSES_LOW, TRIANGLE_MARGIN
    use unused_arg, only: unused
    use record_split, only: release_spans, segment_of, span_text
    use tare_file, only: RIG_KEYS, tare_file_t, read_tare_file, check_same_rig, is_shared_input, &
        shared_sensitivity, tare_own_rows
    use analysis_base, only: ranks_note, resume_note
    implicit none

    !> One release analysed alone (module measurement's release_t is the release; this is
    !! what its fit found).
    type :: release_fit_t
        real(dp) :: i1 = 0.0_dp                 !! its I1 (all that hung)
        real(dp) :: u_own = 0.0_dp              !! the u only this release has
        real(dp) :: nu_own = NU_INFINITE        !! its degrees of freedom
        real(dp), allocatable :: c(:)           !! dI1/dx for the common inputs x
        type(budget_row_t), allocatable :: own(:)   !! the rows of u_own
        real(dp), allocatable :: nu_row(:)      !! each own row's degrees of freedom
        real(dp) :: i1_linear = 0.0_dp, period_linear = 0.0_dp
        real(dp) :: amp_max = 0.0_dp            !! largest amplitude (degrees)
        type(rig_t) :: rg                       !! its rig
        logical :: from_record = .false.
        ! periods
        real(dp), allocatable :: per(:), amps(:), u_each(:), model_periods(:)
        real(dp), allocatable :: cycles(:)
        real(dp) :: u_scatter = -1.0_dp
        logical :: exact = .true.
        ! a record
        type(record_t) :: rec
        real(dp), allocatable :: model(:)       !! the fitted model (rad or rad/s)
        real(dp), allocatable :: jac(:, :)      !! the Jacobian at the estimate
        real(dp), allocatable :: hw(:)          !! the robust weights' roots
        real(dp), allocatable :: dpdx(:, :)     !! (np, inputs) the parameters' sensitivities
        integer :: np = 1, ifirst = 1
        character(len=16) :: names(13) = ''
        real(dp) :: p(13) = 0.0_dp, u_p(13) = 0.0_dp, u_p_own(13) = 0.0_dp
        !> what the record determines (I2, I3, cg_depth, tilt or sway estimated)
        logical :: determined = .false.
        type(determines_t) :: det
        real(dp) :: u_prior(13) = 0.0_dp
        real(dp) :: sigma = 0.0_dp, tau = 1.0_dp, n_eff = 0.0_dp, u_fit = 0.0_dp
        logical :: sigma_stated = .false.
        real(dp) :: residual_rms = 0.0_dp
        integer :: iterations = 0, evaluations = 0, samples = 0
        integer(int64) :: crc = 0               !! its record file's CRC-64
        type(warning_t), allocatable :: warnings(:)
        !> The fit's self-check (periods with stated u): tested, consistent, Birge ratio
        logical :: fit_tested = .false., fit_consistent = .true.
        real(dp) :: fit_birge = 0.0_dp
    end type release_fit_t

    ! TRIANGLE_MARGIN: an I1 more than this factor above I2 + I3 (or below |I2 - I3| over
    ! it) is refused (module work_estimate, which checks it on the classical I1 before the
    ! work).  The classical I1 is compared with what the model gives for the rig at the
    ! fitted I1 (check_linear_gap).

contains

    !> The preconditions of analyses = 'identify', checked before any computing: the
    !! paper's model; one of periods, a record or a table of releases; I1 estimated (and
    !! only I1 from periods); the measurement read into its model (module measurement_read:
    !! the deck's release or the table's, each period divided by its cycles once); every
    !! release readable (its record sound and long enough), and what no rig gives refused at
    !! once (module work_estimate: periods or a record's swing far beyond the rig's, the
    !! classical I1 beyond the triangle inequality, a record sampled too coarsely, with a
    !! long gap, in degrees without record_units); Monte Carlo only for the deck's own
    !! release.  Each record is read once, into its observation, with its CRC-64.  A release
    !! that fails stops the run, or with &measurement on_failure = 'skip' is left out (named
    !! with its row).  The work is estimated; when it is long, one note line says so.  A
    !! period no positive I1 gives is refused by the fit itself (module period_inversion),
    !! before any file is written.
    module procedure identify_ready
        type(measurement_t) :: m
        type(pendulum_t) :: p
        real(dp) :: secs, total
        character(len=:), allocatable :: what, first_what
        type(status_t) :: first_failure
        integer :: i, nsrc, nfirst
        stat%code = 0
        if (trim(d%scene%model) /= 'kane') then
            call set_error(stat, ERR_DECK, 'analyses = ''identify'': &scene model = '''// &
                trim(d%scene%model)//''': identify fits the paper''s model; allowed: '// &
                'model = ''kane''')
            return
        end if
        nsrc = count([d%measurement%n_periods > 0, len_trim(d%measurement%record) > 0, &
                      len_trim(d%measurement%trials) > 0])
        if (nsrc /= 1) then
            call set_error(stat, ERR_DECK, 'analyses = ''identify'': &measurement needs '// &
                'one of periods (with amplitudes), record or trials; allowed: periods = '// &
                '15.2, 15.5, cycles = 10, amplitudes = 10, 10 or record = ''swing.csv'' or '// &
                'trials = ''releases.csv''')
            return
        end if
        call make_pendulum(rig_of(d), p, stat)
        call check_not_tipping(rig_of(d), d%suspension%cables, stat)
        if (stat%code /= 0) return
        if (.not. d%measurement%estimated('I1')) then
            call set_error(stat, ERR_DECK, '&measurement estimate = '''// &
                trim(d%measurement%estimate)//''': I1 is what identify estimates; allowed: '// &
                '''I1'' followed by any of c_v, c_q, amplitude, t0, bias (with a record)')
            return
        end if
        if (len_trim(d%measurement%trials) > 0 .and. d%measurement%monte_carlo > 0) then
            call set_error(stat, ERR_DECK, '&measurement monte_carlo = '// &
                itoa(d%measurement%monte_carlo)//' with trials: the Monte Carlo draws one '// &
                'release; allowed: monte_carlo = 0 with trials (the releases'' scatter is '// &
                'their Type A part), or periods or a record with monte_carlo')
            return
        end if
        if (d%measurement%record_split) then
            call check_split_deck(d, stat)
            if (stat%code /= 0) return
        end if
        call read_releases(d%measurement, rig_of(d), start_of(d), d%suspension%cables, &
                           deck_inputs(d, .true.), m, stat, d%start%gave('amplitude'))
        if (stat%code /= 0) return
        call check_amplitude_scale(d, m, stat)
        if (stat%code /= 0) return
        if (len_trim(d%measurement%calibration) > 0) &
            call calibrate_measurement(d%measurement, m, stat)
        if (stat%code /= 0) return
        if (len_trim(d%measurement%tare) > 0) call ready_tare_file(d, m, stat)
        if (stat%code /= 0) return
        total = 0.0_dp
        first_what = ''
        nfirst = 0
        first_failure%code = 0
        do i = 1, size(m%releases)
            call ready_release(d, m, i, secs, what, stat)
            if (stat%code /= 0) then
                if (trim(d%measurement%on_failure) /= 'skip') return
                if (first_failure%code == 0) first_failure = stat
                call skip_release(m, i, stat)
                cycle
            end if
            total = total + secs
            if (nfirst == 0) then
                first_what = what
                nfirst = i
            end if
        end do
        if (nfirst == 0) then
            ! every release failed: the first failure
            stat = first_failure
            return
        end if
        if (d%measurement%record_split) then
            call split_measurement(d, m, stat)
            if (stat%code /= 0) return
        end if
        if (size(m%releases) > 1) first_what = itoa(size(m%releases))//' releases, the '// &
            'first: '//first_what
        call work_note(d%path, total, first_what)
        if (present(input)) then
            input%ready = .true.
            call move_alloc(m%releases, input%m%releases)
            call move_alloc(m%obs, input%m%obs)
            call move_alloc(m%inputs, input%m%inputs)
            call move_alloc(m%tares, input%m%tares)
            input%m%source = m%source
            input%m%from_table = m%from_table
        end if
    end procedure identify_ready

    !> A tare read from its own output (&measurement tare = 'FILE', module tare_file):
    !! refused with tare_I1 or u_tare_I1 (one tare, one way), with a Monte Carlo (the
    !! first-order budget carries the correlation), from another rig or calibration, or when
    !! a shared input has a u in one run and none in the other.
    subroutine ready_tare_file(d, m, stat)
        type(deck_t), intent(in) :: d
        type(measurement_t), intent(in) :: m
        type(status_t), intent(inout) :: stat
        type(tare_file_t) :: t
        type(rig_calibration_t) :: cal
        character(len=:), allocatable :: key
        real(dp) :: c
        logical :: found, given
        integer :: j
        key = '&measurement tare'
        if (d%measurement%tare_i1 /= 0.0_dp .or. d%measurement%u_tare_i1 /= 0.0_dp) then
            call set_error(stat, ERR_DECK, key//' = '//quoted(trim(d%measurement%tare))// &
                ' with tare_I1 = '//rshort(d%measurement%tare_i1)//', u_tare_I1 = '// &
                rshort(d%measurement%u_tare_i1)//': two tares; allowed: tare = ''FILE'' (a '// &
                'tare measured on this rig) or tare_I1 with its u (one measured elsewhere)')
            return
        end if
        if (d%measurement%monte_carlo > 0) then
            call set_error(stat, ERR_DECK, key//' = '//quoted(trim(d%measurement%tare))// &
                ' with monte_carlo = '//itoa(d%measurement%monte_carlo)//': the Monte '// &
                'Carlo draws this run alone; allowed: monte_carlo = 0 with a tare from its '// &
                'file (the first-order budget carries the shared inputs'' correlation)')
            return
        end if
        call read_tare_file(d%measurement%tare_path, key, t, stat)
        if (stat%code /= 0) return
        if (len_trim(d%measurement%calibration) > 0) then
            call read_calibration_file(d%measurement%calibration_path, 'calibration', cal, stat)
            if (stat%code /= 0) return
        end if
        call check_same_rig(t, key, [d%suspension%l, d%suspension%l_prime, d%suspension%b, &
            d%suspension%b_prime, d%suspension%g], [d%measurement%u_l, &
            d%measurement%u_l_prime, d%measurement%u_b, d%measurement%u_b_prime, &
            d%measurement%u_g], len_trim(d%measurement%calibration) > 0, cal%delta_l, &
            cal%scale, stat)
        if (stat%code /= 0) return
        do j = 1, size(m%inputs)
            if (.not. is_shared_input(m%inputs(j)%name)) cycle
            given = m%inputs(j)%u > 0.0_dp
            call shared_sensitivity(t, m%inputs(j)%name, c, found)
            if (given .eqv. found) cycle
            call set_error(stat, ERR_DECK, key//' = '//quoted(trim(d%measurement%tare))// &
                ': the input '//trim(m%inputs(j)%name)//' the two runs share has a u in '// &
                trim(merge('this deck and not in the tare''s', &
                           'the tare''s and not in this deck', given))//'; allowed: '// &
                'the same u_'//trim(m%inputs(j)%name)//' in both decks (the same tape, '// &
                'the same rig)')
            return
        end do
    end subroutine ready_tare_file

    !> Release i of a measurement against what identify needs (see identify_ready): its
    !! timings against its rig, or its record read (once, with its CRC-64) and checked; the
    !! work it asks for (seconds, in words).  A failure names the release.
    subroutine ready_release(d, m, i, secs, what, stat)
        type(deck_t), intent(in) :: d
        type(measurement_t), intent(inout) :: m
        integer, intent(in) :: i
        real(dp), intent(out) :: secs
        character(len=:), allocatable, intent(out) :: what
        type(status_t), intent(out) :: stat
        type(pendulum_t) :: p
        type(measurement_group_t) :: mea
        real(dp) :: y0(NSTATE), th0(5)
        character(len=:), allocatable :: bytes, name
        integer :: k, nup, n
        stat%code = 0
        secs = 0.0_dp
        what = ''
        mea = mea_of(d, m%releases(i))
        associate (rg => m%releases(i)%rig)
        k = m%record_of(i)
        if (k == 0) then
            if (count_words(mea%estimate) /= 1 + merge(1, 0, mea%estimated('amplitude_scale'))) &
                then
                call set_error(stat, ERR_DECK, estimate_name(d, m, i)//' = '''// &
                    trim(mea%estimate)//''': with periods only I1 (and amplitude_scale) is '// &
                    'estimated; allowed: ''I1'' or ''I1 amplitude_scale'' (c_v, c_q, '// &
                    'amplitude, t0, bias need a record)')
                return
            end if
            if (mea%estimated('amplitude_scale')) then
                call check_scale_release(m, i, estimate_name(d, m, i), stat)
                if (stat%code /= 0) return
            end if
            call make_pendulum(rg, p, stat)
            if (stat%code /= 0) then
                call in_trial(m, i, stat)
                return
            end if
            ! periods no rig gives, a classical I1 beyond the triangle: refused now
            call check_timings(d%body, rg, m%periods_of(i), m%amplitudes_of(i), &
                               .not. m%from_table, stat)
            if (stat%code /= 0) then
                call in_trial(m, i, stat)
                return
            end if
            n = size(m%of_release(i))
            nup = count(m%u_totals_of(i) > 0.0_dp)
            if (nup == 0 .and. n >= 2) nup = n
            call periods_work(d, rg, m%periods_of(i), m%amplitudes_of(i), nup, secs, what)
        else
            name = record_name(d, m, i)
            associate (o => m%obs(k))
                call read_record_file(o%file, record_format_of(d), o%rec, stat, bytes)
                if (stat%code /= 0) then
                    stat%msg = name//': '//stat%msg
                    return
                end if
                o%crc = crc64_of(bytes)
                o%have_record = .true.
                deallocate (bytes)
                call check_record(d, mea, rg, o%rec, name, stat)
                if (stat%code /= 0) return
                call make_pendulum(rg, p, stat)
                if (stat%code == 0) call start_state(start_of(d), p, y0, th0, stat)
                if (stat%code /= 0) then
                    call in_trial(m, i, stat)
                    return
                end if
                ! a swing no rig gives (times in ms), too coarse, a long gap, degrees
                call check_record_times(d%body, d%measurement, d%start, rg, o%rec, name, stat)
                if (stat%code /= 0) return
                ! an angle declared a rate, or a rate an angle, where the release shows
                call check_record_kind(o%rec, d%measurement, trim(d%start%mode) == 'raised', &
                                       name, stat)
                if (stat%code /= 0) return
                if (len_trim(o%rec%note) > 0) call say_note(d%path, name//': '//trim(o%rec%note))
                call record_work(d, mea, o%rec, secs, what)
            end associate
        end if
        end associate
    end subroutine ready_release

    !> &measurement record_split = .true. asks for a record (not periods nor trials), t0
    !! estimated (each segment's release is found in it) and no Monte Carlo (the releases'
    !! scatter is their Type A part, as a table's).
    subroutine check_split_deck(d, stat)
        type(deck_t), intent(in) :: d
        type(status_t), intent(out) :: stat
        stat%code = 0
        if (len_trim(d%measurement%record) == 0) then
            call set_error(stat, ERR_DECK, '&measurement record_split = .true. without '// &
                'record: it cuts one record at its releases; allowed: record = ''FILE'' '// &
                'with record_split, or record_split = .false.')
        else if (.not. d%measurement%estimated('t0')) then
            call set_error(stat, ERR_DECK, '&measurement record_split = .true. with '// &
                'estimate = '''//trim(d%measurement%estimate)//''': each segment''s '// &
                'release is found in it; allowed: an estimate with t0 (''I1 t0'', '// &
                '''I1 t0 bias'')')
        else if (d%measurement%monte_carlo > 0) then
            call set_error(stat, ERR_DECK, '&measurement monte_carlo = '// &
                itoa(d%measurement%monte_carlo)//' with record_split: the Monte Carlo '// &
                'draws one release; allowed: monte_carlo = 0 with record_split (the '// &
                'segments'' scatter is their Type A part)')
        end if
    end subroutine check_split_deck

    !> The deck's record cut at its releases (module record_split): each segment a release
    !! of its own (labelled with its time span), pooled as a table's.  A record of one
    !! release is left whole (the fit is the record's as without record_split).  A segment
    !! whose swing lasts less than two periods after its release (record_fit's find_release)
    !! is refused naming its time span, or with on_failure = 'skip' left out with that
    !! failure (a warning of the output).
    subroutine split_measurement(d, m, stat)
        type(deck_t), intent(in) :: d
        type(measurement_t), intent(inout) :: m
        type(status_t), intent(out) :: stat
        type(release_t), allocatable :: rels(:)
        type(observation_t), allocatable :: obs(:)
        type(record_start_t) :: rl
        type(record_t) :: seg
        integer, allocatable :: lo(:), hi(:)
        real(dp) :: tp
        integer :: k, j, nh, nseg
        logical :: rate
        character(len=:), allocatable :: span
        stat%code = 0
        k = m%record_of(1)
        if (k == 0 .or. size(m%releases) /= 1) return
        associate (rec => m%obs(k)%rec)
            tp = record_swing_period(rec)
            if (.not. (tp > 0.0_dp)) tp = mean_period(rec)
            call release_spans(rec, tp, lo, hi, nh)
            nseg = size(lo)
            if (nseg == 1 .and. lo(1) == 1 .and. hi(1) == size(rec%v)) return
            rate = rec%rate .or. trim(d%measurement%quantity) == 'rate'
            allocate (rels(nseg), obs(nseg))
            do j = 1, nseg
                rels(j) = m%releases(1)
                rels(j)%label = 'segment '//itoa(j)//', '//span_text(rec, lo(j), hi(j))
                rels(j)%line = 0
                obs(j) = m%obs(k)
                obs(j)%release = j
                obs(j)%rec = segment_of(rec, lo(j), hi(j))
            end do
        end associate
        call move_alloc(rels, m%releases)
        call move_alloc(obs, m%obs)
        m%from_table = .true.
        m%source = '&measurement record_split'
        do j = 1, nseg
            seg = m%obs(j)%rec
            span = span_text(seg, 1, size(seg%v))
            stat%code = 0
            if (size(seg%v) < MIN_SAMPLES) then
                call set_error(stat, ERR_DECK, '&measurement record_split: the segment '// &
                    span//' has '//itoa(size(seg%v))//' samples, too few to fit; allowed: '// &
                    'a segment of at least '//itoa(MIN_SAMPLES)//' samples and two periods '// &
                    'of swing after its release, or on_failure = ''skip''')
            else
                call find_release(seg, rate, rl)
                if (seg%t(size(seg%v)) - rl%t0 < 2.0_dp*tp) call set_error(stat, ERR_DECK, &
                    '&measurement record_split: the segment '//span//' swings '// &
                    trim(sci(seg%t(size(seg%v)) - rl%t0, 3))//' s after its release, too '// &
                    'short to fit; allowed: at least two periods of swing ('// &
                    trim(sci(2.0_dp*tp, 3))//' s) after each release, or on_failure = ''skip''')
            end if
            if (stat%code == 0) call check_record_kind(seg, d%measurement, &
                trim(d%start%mode) == 'raised', '&measurement record_split, segment '//span, stat)
            if (stat%code /= 0) then
                if (trim(d%measurement%on_failure) /= 'skip') return
                call skip_release(m, j, stat)
            end if
        end do
        if (all(m%releases%skipped)) call set_error(stat, ERR_DECK, &
            '&measurement record_split: no segment of the record is long enough to fit; '// &
            'allowed: at least two periods of swing after each release')
    end subroutine split_measurement

    !> Release i left out (&measurement on_failure = 'skip'): marked, with its failure
    !! (stat, which names the release and its row), and stat cleared.
    subroutine skip_release(m, i, stat)
        type(measurement_t), intent(inout) :: m
        integer, intent(in) :: i
        type(status_t), intent(inout) :: stat
        m%releases(i)%skipped = .true.
        m%releases(i)%failure = stat%msg
        if (index(stat%msg, m%named(i)) == 0) m%releases(i)%failure = m%named(i)//': '// &
            stat%msg
        stat%code = 0
        stat%msg = ''
    end subroutine skip_release

    !> The &measurement group as release r's fit takes it: the deck's, with the release's
    !! own estimate (a column estimate of the table of releases).
    pure function mea_of(d, r) result(mea)
        type(deck_t), intent(in) :: d
        type(release_t), intent(in) :: r
        type(measurement_group_t) :: mea
        mea = d%measurement
        if (allocated(r%estimate)) mea%estimate = r%estimate
    end function mea_of

    !> How release i's estimate is named in messages: the deck's key, or the table's
    !! column for a release with an estimate of its own.
    function estimate_name(d, m, i) result(s)
        type(deck_t), intent(in) :: d
        type(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        s = '&measurement estimate'
        if (.not. allocated(m%releases(i)%estimate)) return
        if (trim(m%releases(i)%estimate) /= trim(d%measurement%estimate)) &
            s = m%source//', '//m%named(i)//', estimate'
    end function estimate_name

    !> The work of a release of timed periods (per cycle, at amps degrees; nup of them with
    !! a u), in wall seconds (module work_estimate's count of model periods times one period
    !! timed now at the classical I1 of the longest timing: several of pure torsion, which
    !! are cheap, for the clock) and in words.
    subroutine periods_work(d, rg, per, amps, nup, seconds, what)
        type(deck_t), intent(in) :: d
        type(rig_t), intent(in) :: rg
        real(dp), intent(in) :: per(:), amps(:)
        integer, intent(in) :: nup
        real(dp), intent(out) :: seconds
        character(len=:), allocatable, intent(out) :: what
        type(status_t) :: st
        real(dp) :: i1p, tp, one, runs
        integer(int64) :: c0, c1, rate
        integer :: imax, k, reps
        logical :: sym
        seconds = 0.0_dp
        what = ''
        if (size(per) == 0) return
        sym = is_torsion_rig(rg)
        imax = maxloc(per, 1)
        i1p = max(linear_inertia(rg, per(imax)), 1.0e-9_dp*rg%mass*rg%b_prime**2)
        reps = merge(20, 1, sym)
        call system_clock(c0, rate)
        do k = 1, reps
            if (sym) then
                call torsion_period_s(rg, i1p, amps(imax), tp, st)
            else
                call simulated_period_s(rg, accuracy_of(d), i1p, amps(imax), tp, st)
            end if
        end do
        call system_clock(c1)
        one = real(c1 - c0, dp)/real(rate, dp)/reps
        call periods_runs(deck_inputs(d, .false.), d%measurement, size(per), nup, sym, one, runs, &
                          what)
        seconds = runs*one
    end subroutine periods_work

    !> The work of a record fit, in wall seconds (module work_estimate's count of runs over
    !! the whole record times one run timed now over its first five periods, scaled to its
    !! span) and in words.
    subroutine record_work(d, mea, rec, seconds, what)
        type(deck_t), intent(in) :: d
        type(measurement_group_t), intent(in) :: mea    !! the release's (its estimate)
        type(record_t), intent(in) :: rec
        real(dp), intent(out) :: seconds
        character(len=:), allocatable, intent(out) :: what
        type(record_fit_t) :: prob
        type(status_t) :: st
        real(dp), allocatable :: p0(:), h(:), r(:)
        real(dp) :: tsw, span, part, one, runs, ta, tg
        integer(int64) :: c0, c1, rate
        integer :: n
        seconds = 0.0_dp
        what = ''
        n = size(rec%t)
        if (n < 3) return
        call fit_problem(rig_of(d), start_of(d), accuracy_of(d), mea, rec, prob, p0, h)
        span = rec%t(n) - rec%t(prob%ifirst)
        if (.not. mea%estimated('t0')) span = rec%t(n)
        tsw = record_swing_period(rec)
        if (.not. (tsw > 0.0_dp)) then
            call reference_periods(d%body, prob%rg, ta, tg)
            tsw = max(ta, tg)
        end if
        prob%nuse = max(prob%ifirst + 1, min(n, count(rec%t <= rec%t(prob%ifirst) + &
                                                      5.0_dp*tsw)))
        part = rec%t(prob%nuse) - rec%t(prob%ifirst)
        if (.not. mea%estimated('t0')) part = rec%t(prob%nuse)
        allocate (r(prob%nres()))
        call system_clock(c0, rate)
        call prob%residual(p0, r, st)
        call system_clock(c1)
        one = real(c1 - c0, dp)/real(rate, dp)
        if (part > 0.0_dp) one = one*max(1.0_dp, span/part)
        call record_runs(deck_inputs(d%suspension, d%body, mea, d%start, .true.), mea, &
                         d%integration, prob%np, span, span/max(tsw, tiny(1.0_dp)), one, runs, &
                         what)
        seconds = runs*one
    end subroutine record_work

    !> A record's checks beyond its file: times the model can run, long enough to show a
    !! swing, more samples than parameters, 'amplitude' only with a raised start.
    subroutine check_record(d, mea, rg, rec, name, stat)
        type(deck_t), intent(in) :: d
        type(measurement_group_t), intent(in) :: mea    !! the release's (its estimate)
        type(rig_t), intent(in) :: rg
        type(record_t), intent(in) :: rec
        character(len=*), intent(in) :: name    !! for messages
        type(status_t), intent(out) :: stat
        real(dp) :: t_max, span
        integer :: n, np
        stat%code = 0
        n = size(rec%t)
        ! the model runs from the release to the last sample: no longer than a simulation
        ! may run (a record of huge times would run the integrator for ever); times count
        ! from the release unless t0 is estimated
        t_max = TAU_END_MAX/sqrt(rg%g/rg%b_prime)
        span = rec%t(n)
        if (mea%estimated('t0')) span = rec%t(n) - rec%t(1)
        if (span > t_max) then
            call set_error(stat, ERR_DECK, name//': it spans '//sci(span)//' s from the '// &
                'release, beyond what the model runs; allowed: up to '//sci(t_max)// &
                ' s (tau = t sqrt(g/b_prime) <= '//sci(TAU_END_MAX)//', as &integration '// &
                'tau_end)')
            return
        end if
        ! a record that ends within a thousandth of the time scale (b_prime/g)^(1/2) of the
        ! release holds the release alone: nothing to identify, and steps at roundoff
        if (span < 1.0e-3_dp*t_max/TAU_END_MAX) then
            call set_error(stat, ERR_DECK, name//': its last sample, t = '// &
                sci(rec%t(n))//' s, is too early to show a swing; allowed: records '// &
                'spanning at least '//sci(1.0e-3_dp*t_max/TAU_END_MAX)//' s (tau >= 1e-3)')
            return
        end if
        if (mea%estimated('amplitude') .and. trim(d%start%mode) /= 'raised') then
            call set_error(stat, ERR_DECK, '&measurement estimate = '''// &
                trim(mea%estimate)//''': amplitude is the raised start''s; '// &
                'allowed with &start mode = ''raised''')
            return
        end if
        np = count_words(mea%estimate)
        if (n <= np) then
            call set_error(stat, ERR_DECK, name//': '//itoa(n)//' samples for '//itoa(np)// &
                ' parameters; allowed: more samples than parameters')
            return
        end if
    end subroutine check_record

    !> The amplitudes' common scale against what it needs (ERR_DECK): periods, not a
    !! record (a record's amplitude is its release's, with u_amplitude or estimated);
    !! u_amplitude_scale or estimate amplitude_scale, not both; no Monte Carlo (it draws
    !! no scale).
    subroutine check_amplitude_scale(d, m, stat)
        type(deck_t), intent(in) :: d
        type(measurement_t), intent(in) :: m
        type(status_t), intent(out) :: stat
        type(measurement_group_t) :: mea
        logical :: est
        integer :: i
        stat%code = 0
        est = d%measurement%estimated('amplitude_scale')
        do i = 1, size(m%releases)
            mea = mea_of(d, m%releases(i))
            est = est .or. mea%estimated('amplitude_scale')
        end do
        if (.not. est .and. .not. d%measurement%u_amplitude_scale > 0.0_dp) return
        if (any([(m%record_of(i) > 0, i=1, size(m%releases))])) then
            call set_error(stat, ERR_DECK, '&measurement '//trim(merge('estimate          ', &
                'u_amplitude_scale ', est))//': the amplitudes'' scale is one of timed '// &
                'periods, not of a record; allowed: with a record, u_amplitude or estimate '// &
                'amplitude (the release''s)')
        else if (est .and. d%measurement%u_amplitude_scale > 0.0_dp) then
            call set_error(stat, ERR_DECK, '&measurement u_amplitude_scale = '// &
                rshort(d%measurement%u_amplitude_scale)//' with estimate amplitude_scale: '// &
                'the scale is either known to its u or fitted; allowed: one of them')
        else if (d%measurement%monte_carlo > 0) then
            call set_error(stat, ERR_DECK, '&measurement monte_carlo = '// &
                itoa(d%measurement%monte_carlo)//' with the amplitudes'' scale: the Monte '// &
                'Carlo draws no scale; allowed: monte_carlo = 0 (the first-order budget '// &
                'carries it)')
        end if
    end subroutine check_amplitude_scale

    !> Release i of periods with its amplitudes' scale estimated: at least three periods,
    !! at two amplitudes or more (the scale is read from the period-amplitude relation).
    subroutine check_scale_release(m, i, name, stat)
        type(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        character(len=*), intent(in) :: name    !! the estimate's key, for the message
        type(status_t), intent(out) :: stat
        real(dp) :: amin, amax
        integer :: na
        character(len=:), allocatable :: at
        stat%code = 0
        na = size(m%amplitudes_of(i))
        amin = minval(m%amplitudes_of(i))
        amax = maxval(m%amplitudes_of(i))
        if (na >= 3 .and. amax > amin*(1.0_dp + 1.0e-6_dp)) return
        at = 'all at '//fixed(amin, 3)//' deg'
        if (amax > amin*(1.0_dp + 1.0e-6_dp)) at = 'at '//fixed(amin, 3)//' to '// &
            fixed(amax, 3)//' deg'
        call set_error(stat, ERR_DECK, name//' = ''I1 amplitude_scale'': '// &
            itoa(na)//' period(s) '//at// &
            ': the scale needs the periods'' change with amplitude; allowed: at least '// &
            'three periods at two amplitudes or more (e.g. 10 and 40 degrees), or '// &
            'u_amplitude_scale')
        call in_trial(m, i, stat)
    end subroutine check_scale_release

    !> How release i's record is named in messages.
    function record_name(d, m, i) result(s)
        type(deck_t), intent(in) :: d
        type(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        if (m%from_table) then
            s = m%source//', '//m%named(i)//', record '//quoted(m%obs(m%record_of(i))%file)
        else
            s = '&measurement record = '//quoted(d%measurement%record)
        end if
    end function record_name

    !> A failure of release i of a table: the message names it.
    subroutine in_trial(m, i, stat)
        type(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        type(status_t), intent(inout) :: stat
        if (m%from_table) stat%msg = m%named(i)//': '//stat%msg
    end subroutine in_trial

    !> Run analyses = 'identify' for a deck and write OUTDIR/NAME.identify and the figure's
    !! data (NAME.fit.dat for records, NAME.periods.dat for periods) into `files`.  The
    !! Monte Carlo is a sweep over the ranks and threads, checkpointed to
    !! OUTDIR/NAME.identify_mc.partial (options: --resume and the interval; report: how its
    !! sweep went, ranks 1 without Monte Carlo).
    module procedure run_identify
        real(dp) :: c0, c1
        type(cert_figure_data_t) :: fig
        type(sweep_report_t) :: rep
        type(release_fit_t), allocatable :: rels(:)
        type(identify_input_t) :: own
        logical :: have
        call cpu_time(c0)
        rep%note = ''
        have = .false.
        if (present(input)) have = input%ready
        if (have) then
            call identify_releases(d, input%m, res, rels, stat, outdir, options, rep, files)
        else
            ! read (once) and checked here: the driver's identify_ready kept nothing
            call identify_ready(d, stat, own)
            if (stat%code == 0) call identify_releases(d, own%m, res, rels, stat, outdir, &
                                                       options, rep, files)
        end if
        if (present(report)) report = rep
        call cpu_time(c1)
        res%cpu_seconds = c1 - c0
        if (stat%code /= 0) return
        call write_identify(d, outdir, res, rels, files, stat)
        if (stat%code /= 0) return
        if (res%from_record) then
            call write_fit(d, outdir, rels, files, stat, fig)
        else
            call write_periods(d, outdir, rels, res, files, stat, fig)
        end if
        if (stat%code /= 0) return
        call write_identify_certificate(d, outdir, res, fig, files, stat)
    end procedure run_identify

    !> The standard uncertainties of a deck's inputs.
    pure function input_u(d) result(u)
        type(deck_t), intent(in) :: d
        type(input_u_t) :: u
        associate (m => d%measurement)
            u = input_u_t(mass=m%u_mass, l=m%u_l, l_prime=m%u_l_prime, b=m%u_b, &
                          b_prime=m%u_b_prime, g=m%u_g, period=m%u_period, amplitude=m%u_amplitude)
        end associate
    end function input_u

    !> Every release of the measurement analysed alone (those identify_ready left out
    !! skipped; a release whose analysis fails is left out too with &measurement
    !! on_failure = 'skip', else the run stops), then pooled (combine); the Monte Carlo of
    !! the deck's one release when asked.
    subroutine identify_releases(d, m, res, rels, stat, outdir, options, report, files)
        type(deck_t), intent(in) :: d
        type(measurement_t), intent(in) :: m        !! the measurement, its records read once
        type(identify_result_t), intent(out) :: res
        type(release_fit_t), allocatable, intent(out) :: rels(:)
        type(status_t), intent(out) :: stat
        character(len=*), intent(in), optional :: outdir
        type(sweep_options_t), intent(in), optional :: options
        type(sweep_report_t), intent(inout), optional :: report
        type(out_files_t), intent(in), optional :: files
        type(measurement_t) :: mk
        type(release_fit_t), allocatable :: all(:)
        type(measurement_group_t) :: mea
        type(status_t) :: first_failure
        real(dp) :: mean, sdev
        integer :: i, k
        logical, allocatable :: ok(:)
        stat%code = 0
        mk = m
        ! the amplitudes' scale: an input common to every release (its row once)
        if (d%measurement%u_amplitude_scale > 0.0_dp) mk%inputs = [mk%inputs, &
            input_t('amplitude_scale', 1.0_dp, d%measurement%u_amplitude_scale)]
        allocate (all(size(mk%releases)), ok(size(mk%releases)))
        ok = .not. mk%releases%skipped
        first_failure%code = 0
        do i = 1, size(mk%releases)
            if (.not. ok(i)) cycle
            mea = mea_of(d, mk%releases(i))
            k = mk%record_of(i)
            if (k == 0) then
                call release_periods(d, mea, mk, i, release_inputs(mk%inputs, &
                                     mk%releases(i)%rig), all(i), stat)
            else
                call release_record(d, mea, mk%releases(i)%rig, mk%obs(k)%rec, &
                                    release_inputs(deck_inputs(d%suspension, d%body, mea, &
                                    d%start, .true.), mk%releases(i)%rig), mk%inputs, &
                                    mk%releases(i)%own, all(i), stat)
                all(i)%crc = mk%obs(k)%crc
            end if
            if (stat%code /= 0) then
                call in_trial(mk, i, stat)
                if (trim(d%measurement%on_failure) /= 'skip') return
                if (first_failure%code == 0) first_failure = stat
                call skip_release(mk, i, stat)
                ok(i) = .false.
            end if
        end do
        if (.not. any(ok)) then
            stat = first_failure
            return
        end if
        rels = pack(all, ok)
        call combine(d, mk, pack([(i, i=1, size(ok))], ok), rels, res, stat)
        if (stat%code /= 0) return
        if (d%measurement%monte_carlo > 0) then
            if (res%from_record) then
                call record_monte_carlo(d, rels(1), res, stat, outdir, options, report, files)
            else
                associate (r => rels(1))
                    call period_monte_carlo(d, rig_of(d), accuracy_of(d), &
                                            deck_inputs(d, .false.), &
                                            r%per, r%amps, mc_u(d, r), r%i1, &
                                            d%measurement%monte_carlo, d%measurement%seed, &
                                            mean, sdev, stat, outdir, options, report, files, &
                                            r%cycles)
                end associate
                res%u_i1_mc = sdev**2
                do k = 1, size(mk%tares)
                    res%u_i1_mc = res%u_i1_mc + mk%tares(k)%u**2
                end do
                res%u_i1_mc = sqrt(res%u_i1_mc)
                res%mc_mean = mean - (res%i1_total - res%i1)
            end if
        end if
    end subroutine identify_releases

    !> The uncertainties a periods Monte Carlo draws: the deck's, with the timed totals'
    !! scatter for u_period when that is what the release used.
    pure function mc_u(d, r) result(u)
        type(deck_t), intent(in) :: d
        type(release_fit_t), intent(in) :: r
        type(input_u_t) :: u
        u = input_u(d)
        if (r%u_scatter >= 0.0_dp) u%period = r%u_scatter
    end function mc_u

    !> I1 (and the other parameters asked for) from a record of the deck's rig: the fit,
    !! the first-order budget, Monte Carlo when asked (its sweep checkpointed in outdir
    !! when given, see run_identify).
    module procedure identify_record
        type(release_fit_t) :: rels(1)
        type(measurement_t) :: m
        stat%code = 0
        call read_releases(d%measurement, rig_of(d), start_of(d), d%suspension%cables, &
                           deck_inputs(d, .true.), m, stat, d%start%gave('amplitude'))
        if (stat%code /= 0) return
        call release_record(d, d%measurement, rig_of(d), rec, m%inputs, m%inputs, &
                            m%releases(1)%own, rels(1), stat)
        if (stat%code /= 0) return
        call combine(d, m, [1], rels, res, stat)
        if (stat%code /= 0) return
        if (d%measurement%monte_carlo > 0) call record_monte_carlo(d, rels(1), res, stat, outdir, &
                                                                   options, report, files)
    end procedure identify_record

    !> Is budget row `row` a part of the release's own u (measured anew for it) rather than
    !! common to every release?  Its timings, its amplitudes, its record's fit, and the rig
    !! inputs the table of releases gives per release (rig_own).
    pure logical function own_row(row, rig_own)
        type(budget_row_t), intent(in) :: row
        logical, intent(in) :: rig_own(5)
        select case (row%kind)
        case (ROW_TIMING, ROW_AMPLITUDE, ROW_FIT)
            own_row = .true.
        case (ROW_INPUT)
            own_row = own_rig_input(row%input, rig_own)
        case default
            own_row = .false.
        end select
    end function own_row

    !> Is input x a part of the release's own u (own_row of its row)?
    pure logical function own_input(x, rig_own)
        type(input_t), intent(in) :: x
        logical, intent(in) :: rig_own(5)
        own_input = input_kind(x) == ROW_AMPLITUDE
        if (.not. own_input) own_input = own_rig_input(x%name, rig_own)
    end function own_input

    !> Did the release give the rig input `name` itself (rig_own: RIG_COLUMNS, its columns
    !! l, l_prime, b, b_prime, mass of the table; a platform's one length is column l)?
    pure logical function own_rig_input(name, rig_own)
        character(len=*), intent(in) :: name
        logical, intent(in) :: rig_own(5)
        integer :: k
        own_rig_input = .false.
        do k = 1, 5
            if (rig_own(k) .and. trim(name) == trim(RIG_COLUMNS(k))) own_rig_input = .true.
        end do
        if (rig_own(1) .and. trim(name) == 'length') own_rig_input = .true.
    end function own_rig_input

    !> The kind of the budget row of input x: the release's amplitude (a reading of the
    !! release, ROW_AMPLITUDE), else an input of the rig or body (ROW_INPUT).
    pure integer function input_kind(x) result(kind)
        type(input_t), intent(in) :: x
        kind = ROW_INPUT
        if (trim(x%name) == 'amplitude') kind = ROW_AMPLITUDE
        if (trim(x%name) == 'amplitude_scale') kind = ROW_AMPLITUDE_SCALE
    end function input_kind

    !> A release's budget rows split: its own rows (with their degrees of freedom) and the
    !! sensitivities to the common inputs x (of the measurement, by name).
    subroutine split_rows(rows, nu_rows, x, rig_own, r)
        type(budget_row_t), intent(in) :: rows(:)
        real(dp), intent(in) :: nu_rows(:)
        type(input_t), intent(in) :: x(:)
        logical, intent(in) :: rig_own(5)
        type(release_fit_t), intent(inout) :: r
        integer :: i, j
        allocate (r%c(size(x)), r%own(0), r%nu_row(0))
        r%c = 0.0_dp
        do i = 1, size(rows)
            if (own_row(rows(i), rig_own)) then
                r%own = [r%own, rows(i)]
                r%nu_row = [r%nu_row, nu_rows(i)]
            else
                do j = 1, size(x)
                    if (trim(x(j)%name) == trim(rows(i)%input)) r%c(j) = rows(i)%sensitivity
                end do
            end if
        end do
        r%u_own = 0.0_dp
        r%nu_own = NU_INFINITE
        if (size(r%own) > 0) then
            r%u_own = sqrt(sum(r%own%contribution**2))
            r%nu_own = welch_satterthwaite(r%own%contribution, r%nu_row)
        end if
    end subroutine split_rows

    !> Release i of timed periods: its periods per cycle (each its timed total over its
    !! cycles, divided once when read), inverted to I1 once (module period_inversion), with
    !! its budget.  Without u_period, two timings or more give it as the scatter of the timed
    !! totals about the model (s^2 = sum over n - 1 of ((T_i,model - T_i) cycles_i)^2: a
    !! stopwatch's error is per timing, not per cycle), on n - 1 degrees of freedom: the
    !! inversion then weighs each period by its cycles squared (the timings' u known to that
    !! common factor s), and the budget's inversions take u = s/cycles with u_amplitude.
    subroutine release_periods(d, mea, m, i, x, r, stat)
        type(deck_t), intent(in) :: d
        type(measurement_group_t), intent(in) :: mea    !! the release's (its estimate)
        type(measurement_t), intent(in) :: m
        integer, intent(in) :: i                !! the release
        type(input_t), intent(in) :: x(:)       !! its inputs (its own values)
        type(release_fit_t), intent(out) :: r
        type(status_t), intent(out) :: stat
        type(period_fit_t) :: f
        type(input_u_t) :: u
        type(accuracy_t) :: acc
        type(input_t), allocatable :: xp(:)
        real(dp), allocatable :: nu_rows(:)
        real(dp) :: nu_per, amin, up
        integer :: n, j
        logical, allocatable :: sel(:)
        logical :: scatter, fs, fk
        u = input_u(d)
        ! the amplitudes' scale: estimated (fs), or known to u_amplitude_scale, then fitted
        ! with it as its prior when the timings' u are stated (fk; module period_inversion)
        fs = mea%estimated('amplitude_scale')
        acc = accuracy_of(d)
        r%rg = m%releases(i)%rig
        r%per = m%periods_of(i)
        r%cycles = m%cycles_of(i)
        r%amps = m%amplitudes_of(i)
        r%u_each = m%u_periods_of(i)
        n = size(r%per)
        r%exact = is_torsion_rig(r%rg)
        r%samples = n
        xp = pack(x, x%name /= 'amplitude' .and. x%name /= 'amplitude_scale')
        nu_per = NU_INFINITE
        scatter = all(m%u_totals_of(i) == 0.0_dp) .and. n >= 2
        fk = fs .or. (d%measurement%u_amplitude_scale > 0.0_dp .and. .not. scatter)
        if (scatter) then
            ! the timings' u, known to a common factor: each timed total's the same
            call invert_periods(r%rg, acc, r%per, r%amps, u, f, stat, 1.0_dp/r%cycles, .true., &
                                fit_scale=fs, cycles=r%cycles)
            if (stat%code /= 0) return
            nu_per = n - 1 - merge(1, 0, fs)
            r%u_scatter = sqrt(sum(((f%model_periods - r%per)*r%cycles)**2)/nu_per)
            r%u_each = r%u_scatter/r%cycles
        else
            call invert_periods(r%rg, acc, r%per, r%amps, u, f, stat, r%u_each, fit_scale=fk, &
                                scale_prior=d%measurement%u_amplitude_scale, cycles=r%cycles)
            if (stat%code /= 0) return
        end if
        call period_budget(r%rg, acc, r%per, r%amps, u, f, stat, xp, r%u_each, fk, &
                           d%measurement%u_amplitude_scale, r%cycles)
        if (stat%code /= 0) return
        allocate (r%warnings(0))
        r%fit_tested = f%tested
        r%fit_consistent = f%consistent
        r%fit_birge = f%birge
        if (f%tested .and. .not. f%consistent) then
            ! the periods scatter beyond their u: the period rows inflated by the Birge
            ! ratio, so that u_I1 is not below what the residuals imply
            do j = 1, size(f%budget)
                if (f%budget(j)%kind /= ROW_TIMING) cycle
                f%budget(j)%u = f%budget(j)%u*f%inflation
                f%budget(j)%contribution = f%budget(j)%contribution*f%inflation
            end do
            call add_warning(r%warnings, period_misfit_warning(m, i, r, f))
            ! the Birge ratio is the periods' scatter measured on the fit's dof: the period
            ! rows take those degrees of freedom (Welch-Satterthwaite into k)
            nu_per = real(max(1, f%dof), dp)
        end if
        r%i1 = f%i1
        r%iterations = f%iterations
        r%residual_rms = f%residual_rms
        r%model_periods = f%model_periods
        allocate (nu_rows(size(f%budget)))
        nu_rows = NU_INFINITE
        do j = 1, size(f%budget)
            if (f%budget(j)%kind == ROW_TIMING) nu_rows(j) = nu_per
        end do
        call split_rows(f%budget, nu_rows, m%inputs, m%releases(i)%own, r)
        if (nu_per < NU_INFINITE .and. size(r%own) > 0) then
            ! the period rows share one variance estimate (the scatter, n - 1 dof): one
            ! component for Welch-Satterthwaite
            up = sqrt(sum(r%own%contribution**2, mask=r%own%kind == ROW_TIMING))
            r%nu_own = welch_satterthwaite([up, sqrt(max(0.0_dp, r%u_own**2 - up**2))], &
                                           [nu_per, NU_INFINITE])
        end if
        ! the classical formula from the mean period at the smallest amplitude
        amin = minval(r%amps)
        sel = r%amps <= amin*(1.0_dp + 1.0e-9_dp)
        r%period_linear = sum(r%per, sel)/count(sel)
        r%i1_linear = linear_inertia(r%rg, r%period_linear)
        r%amp_max = maxval(r%amps)
        r%np = 1
        r%names(1) = 'I1'
        r%p(1) = r%i1
        if (fs) then
            ! the amplitudes' scale fitted: its u from every row of the budget (the timing
            ! rows as inflated above), dk/dx from the budget's own inversions
            r%amp_max = r%amp_max*f%scale
            r%np = 2
            r%names(2) = 'amplitude_scale'
            r%p(2) = f%scale
            r%u_p(2) = sqrt(sum((f%scale_c*f%budget%u)**2))
            r%u_p_own(2) = sqrt(sum((f%scale_c*f%budget%u)**2, mask=[(own_row(f%budget(j), &
                                    m%releases(i)%own), j=1, size(f%budget))]))
        end if
    end subroutine release_periods

    !> The warning of periods that do not agree with their u: chi^2 on its dof, p, the
    !! Birge ratio, the period with the largest normalised residual and the likely cause.
    function period_misfit_warning(m, i, r, f) result(msg)
        type(measurement_t), intent(in) :: m
        integer, intent(in) :: i                !! the release
        type(release_fit_t), intent(in) :: r
        type(period_fit_t), intent(in) :: f
        character(len=:), allocatable :: msg
        character(len=:), allocatable :: cause, where
        integer :: k
        real(dp) :: dt
        k = max(1, f%worst)
        dt = r%per(k) - f%model_periods(k)
        if (abs(dt) > 0.2_dp*f%model_periods(k)) then
            cause = 'a period in other units or of another motion (a swing, a half period), '// &
                'or an amplitude far from the one timed'
        else if (abs(dt) > 1.0e-3_dp*f%model_periods(k)) then
            cause = 'a mistyped period, a miscounted cycle or a wrong amplitude'
        else
            cause = 'u_period below the timing''s real scatter'
        end if
        where = trim(m%named(i))
        if (len(where) > 0) where = ' of '//where
        msg = 'identify: the periods'//where//' do not agree with their u (chi^2 = '// &
            sci(f%chi2, 3)//' on '//itoa(f%dof)//' dof, p = '//sci(f%p_value, 2)// &
            ', Birge ratio '//sci(f%birge, 3)//'): period('//itoa(k)//') = '// &
            sci(r%per(k), 6)//' s at '//fixed(r%amps(k), 2)//' deg is '// &
            sci(abs(f%z_worst), 2)//' u from the model''s '//sci(f%model_periods(k), 6)// &
            ' s; likely '//cause//'; the period rows of u_I1 are inflated by the Birge ratio'
    end function period_misfit_warning

    !> One release recorded: the fit (the estimator on growing windows; with loss = 'huber',
    !! its robust loss: reweighted three times), the covariance C = s^2 tau (J^T W J)^-1 (s^2
    !! the residuals' mean square, not below 1 when the record states each sample's u; tau
    !! their correlation time in samples: n/tau independent samples), the inputs'
    !! sensitivities by the implicit-function form.
    subroutine release_record(d, mea, rg, rec, x, xc, rig_own, r, stat)
        type(deck_t), intent(in) :: d
        type(measurement_group_t), intent(in) :: mea    !! the release's (its estimate)
        type(rig_t), intent(in) :: rg
        type(record_t), intent(in) :: rec
        type(input_t), intent(in) :: x(:)       !! the release's inputs (its own values)
        type(input_t), intent(in) :: xc(:)      !! the measurement's common inputs
        logical, intent(in) :: rig_own(5)
        type(release_fit_t), intent(out) :: r
        type(status_t), intent(out) :: stat
        type(record_fit_t) :: prob
        type(lsq_result_t) :: fit
        real(dp), allocatable :: p0(:), h(:), jac(:, :), cov(:, :), dpdx(:, :), e(:)
        real(dp), allocatable :: nu_rows(:)
        type(budget_row_t), allocatable :: rows(:)
        type(lsq_options_t) :: opts        ! the fit's default tolerances
        real(dp) :: s2, se, emean, gain, ratio, rho
        real(dp), allocatable :: es(:)
        real(dp) :: ui(2)
        integer :: m, np, j, ih, i0, nout, lag, ms, k
        character(len=:), allocatable :: umsg, missing
        logical :: follows
        r%from_record = .true.
        r%rg = rg
        r%rec = rec
        call fit_problem(rig_of(d), start_of(d), accuracy_of(d), mea, rec, prob, p0, h)
        prob%rg = rg
        ! the budget's inputs ride along the fit's last runs (record_fit's evaluator)
        call carry_inputs(prob, x)
        np = prob%np
        ! with loss = 'huber' the whole record refitted with Huber's weights (the estimator's
        ! robust loss), which stay the problem's (prob%hw) for its covariance and budget
        call fit_record(prob, p0, h, fit, stat, merge(LOSS_HUBER, LOSS_SQUARES, &
                                                     trim(mea%loss) == 'huber'))
        r%iterations = fit%iterations
        r%evaluations = fit%evaluations
        if (allocated(fit%robust)) prob%hw(prob%ifirst:prob%nuse) = fit%robust
        if (stat%code == ERR_NUMERIC) then
            call explain_fit_failure(stat, prob, fit)
            return
        else if (stat%code /= 0) then
            ! an estimate the record cannot separate (record_fit's check) is named as such
            if (index(stat%msg, '&measurement estimate') /= 1) stat%msg = &
                'the model at the start values: '//stat%msg
            stat%msg = 'identify: '//stat%msg
            return
        end if
        m = prob%nres()
        i0 = prob%ifirst
        ! the Jacobian at the estimate (forward sensitivities: the fit's last; else central
        ! differences), the covariance
        allocate (jac(m, np))
        if (prob%has_jacobian()) then
            ! the fit's last Jacobian, at the estimate; when the fit ended on one taken again
            ! from an earlier point, computed there, and the fit goes on from the estimate
            ! while that Jacobian's Gauss-Newton step is not within the fit's tolerance
            opts%h = h
            opts%names = estimated_names(prob)
            do ih = 1, 3
                if (prob%runs%jac_fresh .or. stat%code /= 0) exit
                call fresh_jacobian(prob, fit%p, fit%r, fit%jac, stat, gain)
                r%evaluations = r%evaluations + 1
                if (stat%code /= 0) exit
                if (gain <= opts%gtol) exit
                p0 = fit%p
                call estimate(prob, p0, opts, fit, stat)
                r%iterations = r%iterations + fit%iterations
                r%evaluations = r%evaluations + fit%evaluations
            end do
            jac = fit%jac
        else
            call lsq_jacobian(prob, fit%p, fit%r, h, jac, stat, central=.true.)
            r%evaluations = r%evaluations + 2*np
        end if
        if (stat%code /= 0) then
            stat%msg = 'identify: the Jacobian at the estimate: '//stat%msg
            return
        end if
        s2 = fit%cost/(m - np)
        r%sigma_stated = .false.
        if (rec%has_u) then
            r%sigma_stated = s2 <= 1.0_dp
            s2 = max(1.0_dp, s2)
        end if
        r%tau = correlation_time(fit%r)
        r%n_eff = m/r%tau
        call lsq_covariance(jac, s2*r%tau, cov, stat, estimated_names(prob))
        if (stat%code /= 0) then
            stat%msg = 'identify: the record: '//stat%msg//'; estimate fewer parameters or '// &
                'use a longer record'
            call explain_fit_failure(stat, prob, fit)
            return
        end if
        allocate (dpdx(np, size(x)))
        call input_sensitivities(prob, fit%p, jac, x, dpdx, ih, stat)
        r%evaluations = r%evaluations + ih
        if (stat%code /= 0) then
            stat%msg = 'identify: '//stat%msg
            return
        end if
        r%dpdx = dpdx
        r%np = np
        r%samples = m
        r%ifirst = i0
        r%sigma = sqrt(s2)
        r%jac = jac
        r%hw = prob%hw
        do j = 1, np
            r%names(j) = PARAM_NAMES(prob%which(j))
            r%p(j) = fit%p(j)
            r%u_p(j) = sqrt(cov(j, j) + sum((dpdx(j, :)*x%u)**2))
            r%u_p_own(j) = sqrt(cov(j, j) + sum((dpdx(j, :)*x%u)**2, &
                                               mask=[(own_input(x(ih), rig_own), &
                                                      ih=1, size(x))]))
        end do
        r%i1 = r%p(1)
        r%u_fit = sqrt(cov(1, 1))
        allocate (rows(0), nu_rows(0))
        rows = [rows, budget_row_t('record', r%sigma, r%sigma*sqrt(r%tau), &
                                   r%u_fit/(r%sigma*sqrt(r%tau)), r%u_fit, ROW_FIT)]
        nu_rows = [nu_rows, max(1.0_dp, r%n_eff - np)]
        do j = 1, size(x)
            if (.not. (x(j)%u > 0.0_dp)) cycle
            rows = [rows, budget_row_t(x(j)%name, x(j)%value, x(j)%u, dpdx(1, j), &
                                       abs(dpdx(1, j))*x(j)%u, input_kind(x(j)))]
            nu_rows = [nu_rows, NU_INFINITE]
        end do
        call split_rows(rows, nu_rows, xc, rig_own, r)
        ms = prob%nuse - i0 + 1
        if (prob%rates) then
            ! the instrument's three rates: e and the model those of the rate about the
            ! vertical they give (W = -omega . b_1), which the record's v holds
            es = fit%r/stacked_weights(prob)
            r%residual_rms = sqrt(sum(es**2)/m)
            allocate (e(ms))
            e = 0.0_dp
            do k = 1, 3
                e = e - prob%axes(k, 1)*es((k - 1)*ms + 1:k*ms)
            end do
            r%determined = .true.
        else if (prob%point) then
            ! a tracked point's two coordinates: e and the model those of the one the
            ! record's v holds (vcol)
            es = fit%r/stacked_weights(prob)
            r%residual_rms = sqrt(sum(es**2)/m)
            e = es((prob%vcol - 1)*ms + 1:prob%vcol*ms)
            r%determined = .true.
        else
            e = fit%r/(prob%w(i0:prob%nuse)*prob%hw(i0:prob%nuse))
            r%residual_rms = sqrt(sum(e**2)/m)
        end if
        r%model = e + prob%rec%v(i0:prob%nuse)
        if (any([(any(prob%which(j) == [P_I2, P_I3, P_CG, P_TILT, P_SWAY]), j=1, np)])) &
            r%determined = .true.
        if (r%determined) then
            ! what the record determines: u against the prior, correlations, condition
            call record_determines(jac, prob%xs(1:np), r%det)
            r%u_prior = 0.0_dp
            do j = 1, np
                select case (prob%which(j))
                case (P_I2)
                    ui = mea%u_inertia_of()
                    r%u_prior(j) = ui(1)
                case (P_I3)
                    ui = mea%u_inertia_of()
                    r%u_prior(j) = ui(2)
                case (P_CG)
                    r%u_prior(j) = mea%u_cg_depth
                end select
            end do
        end if
        ! the model must follow the record (module model_follow): else refused, the
        ! likely causes named
        r%period_linear = mean_period(prob%rec, i0)
        lag = 0
        if (r%period_linear > 0.0_dp .and. ms > 1) lag = nint(r%period_linear* &
            (ms - 1)/(rec%t(prob%nuse) - rec%t(i0)))
        call follows_record(prob%rec%v(i0:prob%nuse), e*prob%hw(i0:prob%nuse), lag, follows, &
                            ratio, rho)
        if (.not. follows) then
            missing = ''
            do j = 2, P_BIAS
                if (.not. mea%estimated(PARAM_NAMES(j))) missing = missing//' '//trim(PARAM_NAMES(j))
            end do
            call set_error(stat, ERR_NUMERIC, not_following_message(ratio, rho, lag, &
                                                                    adjustl(missing)))
            return
        end if
        allocate (r%warnings(0))
        ! the self-check, with each sample's u stated (a record's column U): chi^2 of the
        ! weighted residuals on m - np dof; the covariance above already takes s^2 = max(1,
        ! chi^2/dof), the Birge ratio squared when the samples scatter beyond their u
        if (rec%has_u .and. m > np) then
            r%fit_tested = .true.
            r%fit_birge = sqrt(fit%cost/(m - np))
            r%fit_consistent = chi2_sf(fit%cost, real(m - np, dp)) >= 0.05_dp
            if (.not. r%fit_consistent) call add_warning(r%warnings, &
                record_misfit_warning(rec, i0, fit%r, fit%cost, m - np, r%fit_birge))
        end if
        if (.not. mea%estimated('bias')) then
            ! an offset the fit does not model shows as a mean of the residuals
            emean = sum(e)/m
            se = r%residual_rms*sqrt(r%tau/m)
            if (abs(emean) > 5.0_dp*se .and. abs(emean) > 2.0e-3_dp*maxval(abs(rec%v))) &
                call add_warning(r%warnings, 'identify: the record''s residuals have a '// &
                    'mean of '//sci(-emean/rec%to_rad, 2)//' '//trim(rec%units)//' ('// &
                    itoa(nint(abs(emean)/se))//' standard errors): an offset of the '// &
                    'instrument (a gyro''s bias, an angle''s zero) biases I1 and the '// &
                    'damping; add bias to &measurement estimate')
        end if
        ! a column U that is no u of these samples
        umsg = u_column_warning(prob%rec, i0, e)
        ! (its scatter against U is the self-check's warning above when that fired)
        if (.not. r%fit_consistent .and. index(umsg, 'not small against its swing') == 0) &
            umsg = ''
        if (len(umsg) > 0) call add_warning(r%warnings, umsg)
        ! the classical value from the samples the fit takes as the swing (no dropouts; the
        ! column the fit took as the record's value: a track's larger swing, the vertical rate)
        r%period_linear = clean_mean_period(prob%rec, i0, e, nout)
        if (r%period_linear > 0.0_dp) r%i1_linear = linear_inertia(rg, r%period_linear)
        if (.not. (r%period_linear > 0.0_dp) .and. nout > 0) call say_note(d%path, &
            'identify: the classical value is left out: fewer than two crossings of the '// &
            'swing''s centre remain once '//itoa(nout)//' samples far from the fitted model '// &
            '(dropouts, spikes) are left out')
        r%amp_max = d%start%amplitude
        if (mea%estimated('amplitude')) then
            r%amp_max = r%p(findloc(prob%which(1:np), 4, 1))
            ! the release 57 times (or 1/57 of) the deck's: the record's unit mistaken
            call check_fitted_amplitude(mea, d%start, rec, r%amp_max, &
                                        'identify: the record''s fit', stat)
            if (stat%code /= 0) return
        end if
    end subroutine release_record

    !> The warning of a record whose residuals do not agree with its samples' stated u:
    !! chi^2 on its dof, p, the Birge ratio, the sample with the largest normalised residual
    !! (its time and value) and the likely cause.
    function record_misfit_warning(rec, i0, rw, chi2, dof, birge) result(msg)
        type(record_t), intent(in) :: rec
        integer, intent(in) :: i0               !! the first sample fitted
        real(dp), intent(in) :: rw(:)           !! the weighted residuals, from sample i0
        real(dp), intent(in) :: chi2, birge
        integer, intent(in) :: dof
        character(len=:), allocatable :: msg
        character(len=:), allocatable :: cause
        integer :: k, j
        k = maxloc(abs(rw), 1)
        j = i0 + k - 1
        if (abs(rw(k)) > 5.0_dp*birge .and. abs(rw(k)) > 10.0_dp) then
            cause = 'a spike, a dropout or a mistyped sample there'
        else
            cause = 'a column U below the instrument''s real noise, or a parameter missing '// &
                'from &measurement estimate'
        end if
        msg = 'identify: the record''s residuals do not agree with its samples'' u (chi^2 = '// &
            sci(chi2, 3)//' on '//itoa(dof)//' dof, p = '// &
            sci(chi2_sf(chi2, real(dof, dp)), 2)//', Birge ratio '//sci(birge, 3)// &
            '): the sample at t = '//sci(rec%t(j), 6)//' s, '//sci(rec%v(j)/rec%to_rad, 4)// &
            ' '//trim(rec%units)//', is '//sci(abs(rw(k)), 2)//' u from the model; likely '// &
            cause//'; u_I1_fit is inflated by the Birge ratio'
    end function record_misfit_warning

    !> The releases pooled (module pooling), the common inputs' budget once (their
    !! sensitivities averaged with the pool's weights), the tare and added inertia
    !! subtracted, Welch-Satterthwaite's degrees of freedom and the coverage factor of 95 %;
    !! then the checks of what no body or rig gives (ERR_MODEL).
    subroutine combine(d, m, kept, rels, res, stat)
        type(deck_t), intent(in) :: d
        type(measurement_t), intent(in) :: m    !! the measurement
        integer, intent(in) :: kept(:)          !! the releases pooled (not skipped)
        type(release_fit_t), intent(in) :: rels(:)  !! their fits, in that order
        type(identify_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        type(pooled_t) :: pool, pj
        type(sessions_pooled_t) :: sp
        type(rig_calibration_t) :: cal
        type(budget_row_t), allocatable :: rows(:), trows(:)
        type(budget_row_t) :: crow
        type(tare_file_t) :: tare
        real(dp), allocatable :: uc(:), nuc(:), tnu(:)
        real(dp) :: cbar, u_total, ct, u_total2
        logical :: tared, found
        integer :: n, j, r, k, q, nw
        integer, allocatable :: jr(:)
        character(len=16) :: word
        stat%code = 0
        n = size(rels)
        associate (x => m%inputs)
        ! in one level, or in two when the releases name two sessions or more
        call pool_sessions(rels%i1, rels%u_own, rels%nu_own, &
                           [(session_of(m%releases(kept(r))), r=1, n)], sp)
        pool = sp%pool
        call session_results(sp, res)
        res%n_trials = n
        res%from_record = all(rels%from_record)
        res%consistency = pool%consistency
        if (any(rels%fit_tested)) then
            res%fit_consistency = 'consistent'
            if (any(rels%fit_tested .and. .not. rels%fit_consistent)) &
                res%fit_consistency = 'inconsistent'
            res%fit_birge_ratio = maxval(rels%fit_birge, mask=rels%fit_tested)
        end if
        res%birge_ratio = pool%birge
        res%p_value = pool%p_value
        res%u_i1_random = pool%u_random
        res%u_i1_reproducibility = pool%u_reproducibility
        if (n == 1) then
            rows = rels(1)%own
        else if (sp%n_sessions >= 2) then
            ! the releases within the sessions, and the sessions' scatter: rows of their own
            rows = [budget_row_t('releases', pool%mean, sp%u_within, 1.0_dp, sp%u_within, &
                                 ROW_RELEASE), budget_row_t('u_I1_session', pool%mean, &
                                 sp%u_session, 1.0_dp, sp%u_session, ROW_SESSION)]
        else
            rows = [budget_row_t('releases', pool%mean, pool%u_random, 1.0_dp, pool%u_random, &
                                 ROW_RELEASE)]
        end if
        if (sp%n_sessions >= 2) then
            uc = [sp%u_within, sp%u_session]
            nuc = [sp%nu_within, sp%nu_session]
        else
            uc = [pool%u_random]
            nuc = [pool%nu_random]
        end if
        ! the part measured anew: what a deck taking this output as its tare keeps apart
        res%n_own_rows = size(rows)
        res%u_i1_own = sqrt(sum(uc**2))
        res%dof_own = welch_satterthwaite(uc, nuc)
        tared = len_trim(d%measurement%tare) > 0
        if (tared) then
            call read_tare_file(d%measurement%tare_path, '&measurement tare', tare, stat)
            if (stat%code /= 0) return
        end if
        ! u of all that hung (u_I1_total): the inputs with this run's sensitivities alone
        u_total2 = sum(uc**2)
        do j = 1, size(x)
            if (.not. (x(j)%u > 0.0_dp) .or. own_input(x(j), m%releases(kept(1))%own)) cycle
            cbar = 0.0_dp
            do r = 1, n
                cbar = cbar + pool%weight(r)*rels(r)%c(j)
            end do
            u_total2 = u_total2 + (cbar*x(j)%u)**2
            if (tared .and. is_shared_input(x(j)%name)) then
                ! one error in both runs: the difference of the two sensitivities
                call shared_sensitivity(tare, x(j)%name, ct, found)
                cbar = cbar - ct
            end if
            rows = [rows, budget_row_t(x(j)%name, x(j)%value, x(j)%u, cbar, abs(cbar)*x(j)%u, &
                                       input_kind(x(j)))]
            uc = [uc, abs(cbar)*x(j)%u]
            nuc = [nuc, NU_INFINITE]
        end do
        if (len_trim(d%measurement%calibration) > 0) then
            ! the calibrated constants' covariance: one correlated row
            call read_calibration_file(d%measurement%calibration_path, 'calibration', cal, stat)
            if (stat%code /= 0) return
            ! (with a tare on the same calibration: its sensitivities those of the difference)
            rows = [rows, calibration_row(cal, pool%mean - merge(tare%i1, 0.0_dp, tared), &
                                          d%suspension%l + cal%delta_l)]
            uc = [uc, rows(size(rows))%contribution]
            nuc = [nuc, NU_INFINITE]
            crow = calibration_row(cal, pool%mean, d%suspension%l + cal%delta_l)
            u_total2 = u_total2 + crow%contribution**2
        end if
        res%i1_total = pool%mean
        u_total = sqrt(u_total2)
        res%u_i1_total = u_total
        ! the tares: each subtracted, with its u
        res%i1 = pool%mean
        do k = 1, size(m%tares)
            associate (t => m%tares(k))
                res%i1 = res%i1 - t%value
                rows = [rows, budget_row_t(t%name, t%value, t%u, -1.0_dp, t%u, &
                                           merge(ROW_ADDED, ROW_TARE, t%added))]
                uc = [uc, t%u]
                nuc = [nuc, NU_INFINITE]
            end associate
        end do
        if (tared) then
            ! the tare from its output: its own part and its body's inputs, independent
            res%i1_tare_file = tare%i1
            res%i1 = res%i1 - tare%i1
            call tare_own_rows(tare, trows, tnu)
            rows = [rows, trows]
            uc = [uc, trows%contribution]
            nuc = [nuc, tnu]
        end if
        ! a tare at or above all that hung: no body left to measure
        if (tared .and. .not. (res%i1 > 0.0_dp)) then
            call set_error(stat, ERR_DECK, '&measurement tare = '// &
                quoted(trim(d%measurement%tare))//': its I1 = '//sci(tare%i1, 4)// &
                ' is not below I1 = '//sci(res%i1_total, 4)//', what the rig measured of all '// &
                'that hung; allowed: the output of the empty rig or the fixture alone')
            return
        end if
        if (size(m%tares) > 0 .and. .not. (res%i1 > 0.0_dp)) then
            call set_error(stat, ERR_DECK, '&measurement '//tare_words(m)//': not below '// &
                'I1 = '//sci(res%i1_total, 4)//', what the rig measured of all that hung '// &
                '(the body''s I1 would be '//sci(res%i1, 4)//'); allowed: tare_I1 + '// &
                'added_inertia < the I1 of all that hung; likely: the tare in other units '// &
                'of mass or length than the deck''s, or measured on another rig')
            return
        end if
        res%u_i1 = sqrt(sum(uc**2))
        res%budget = rows
        ! no u of any input, no scatter, no record: u_I1 = 0 means nothing was given
        res%uncertainty_given = .false.
        if (size(rows) > 0) res%uncertainty_given = any(rows%u > 0.0_dp)
        res%record_crc = pack(rels%crc, rels%from_record)
        res%dof_eff = welch_satterthwaite(uc, nuc)
        res%k = coverage_factor(res%dof_eff, 0.95_dp)
        res%u_i1_expanded = res%k*res%u_i1
        allocate (res%trial_label(n), res%trial_session(n), res%skipped(0))
        do r = 1, n
            res%trial_label(r) = m%releases(kept(r))%label
            res%trial_session(r) = ''
            if (allocated(m%releases(kept(r))%session)) &
                res%trial_session(r) = m%releases(kept(r))%session
        end do
        res%n_trials_skipped = m%n_skipped()
        do r = 1, size(m%releases)
            if (.not. m%releases(r)%skipped) cycle
            call add_warning(res%skipped, m%named(r))
        end do
        res%trial_i1 = rels%i1
        res%trial_u = rels%u_own
        ! the classical formula, pooled like I1 (all that hung)
        res%i1_linear = sum(pool%weight*rels%i1_linear)
        res%linear_error = 0.0_dp
        if (res%i1_linear > 0.0_dp) res%linear_error = res%i1_linear/res%i1_total - 1.0_dp
        res%period_linear = rels(1)%period_linear
        ! the parameters: I1, then (records) those estimated with it, in PARAM_NAMES'
        ! order, then (periods) the amplitudes' scale, each pooled alike over the releases
        ! that estimate it (a release may estimate fewer: its own estimate)
        res%np = 1
        res%names = ''
        res%names(1) = 'I1'
        res%p(1) = res%i1
        res%u_p(1) = res%u_i1
        allocate (jr(n))
        do q = 2, size(PARAM_NAMES) + 1
            word = 'amplitude_scale'
            if (q <= size(PARAM_NAMES)) word = PARAM_NAMES(min(q, size(PARAM_NAMES)))
            do r = 1, n
                jr(r) = findloc(rels(r)%names(1:rels(r)%np), word, 1)
            end do
            nw = count(jr > 0)
            if (nw == 0) cycle
            res%np = res%np + 1
            j = res%np
            res%names(j) = word
            if (nw == 1) then
                r = findloc(jr > 0, .true., 1)
                res%p(j) = rels(r)%p(jr(r))
                res%u_p(j) = rels(r)%u_p(jr(r))
            else
                call pool_releases(pack([(rels(r)%p(max(1, jr(r))), r=1, n)], jr > 0), &
                                   pack([(rels(r)%u_p_own(max(1, jr(r))), r=1, n)], jr > 0), &
                                   pack(rels%nu_own, jr > 0), pj)
                res%p(j) = pj%mean
                ! the common inputs' part, the same in every release: averaged, not reduced
                res%u_p(j) = sqrt(pj%u_random**2 + sum(pj%weight*pack([(max(0.0_dp, &
                    rels(r)%u_p(max(1, jr(r)))**2 - rels(r)%u_p_own(max(1, jr(r)))**2), &
                    r=1, n)], jr > 0)))
            end if
        end do
        if (n == 1 .and. rels(1)%determined) then
            ! what the one record determines (its parameters in the same order)
            res%determined = .true.
            res%u_prior = rels(1)%u_prior
            res%correlation_max = rels(1)%det%corr_max
            res%condition = rels(1)%det%cond
            if (all(rels(1)%det%pair > 0)) res%correlation_pair = &
                trim(rels(1)%names(rels(1)%det%pair(1)))//' '// &
                trim(rels(1)%names(rels(1)%det%pair(2)))
        end if
        res%iterations = sum(rels%iterations)
        res%evaluations = sum(rels%evaluations)
        res%samples = sum(rels%samples)
        res%residual_rms = sqrt(sum(rels%residual_rms**2*rels%samples)/max(1, res%samples))
        res%sigma = rels(1)%sigma
        res%sigma_stated = rels(1)%sigma_stated
        res%correlation_time = rels(1)%tau
        res%n_effective = sum(rels%n_eff)
        res%u_i1_fit = rels(1)%u_fit
        res%ifirst = rels(1)%ifirst
        res%u_period_scatter = rels(1)%u_scatter
        if (n == 1 .and. .not. rels(1)%from_record) res%model_periods = rels(1)%model_periods
        if (n == 1 .and. rels(1)%from_record) res%model = rels(1)%model
        res%periods_exact = all(rels%exact .or. rels%from_record)
        if (res%from_record) then
            res%period_model = 'record'
        else
            res%period_model = trim(merge('exact torsion', 'simulated    ', res%periods_exact))
            ! a body off a platform's axis: the platform's orbit (3 cables) or elastic (4+)
            if (size(kept) > 0) then
                if (offaxis_platform(m%releases(kept(1))%rig)) res%period_model = &
                    trim(merge('platform orbit  ', 'platform elastic', &
                               m%releases(kept(1))%rig%cables == 3))
            end if
        end if
        allocate (res%warnings(0))
        do r = 1, size(m%releases)
            ! a release left out: named with its row, and why (on_failure = 'skip')
            if (m%releases(r)%skipped) call add_warning(res%warnings, 'identify: left out '// &
                '(&measurement on_failure = ''skip''): '//m%releases(r)%failure)
        end do
        do r = 1, n
            if (allocated(rels(r)%warnings)) res%warnings = [res%warnings, rels(r)%warnings]
        end do
        if (sp%n_sessions >= 2) then
            call session_warnings(sp, res)
        else if (trim(pool%consistency) == 'inconsistent' .and. all(rels%u_scatter >= 0.0_dp)) then
            ! no u_period: each release's u is the scatter of its own few timings, itself
            ! uncertain; that is the likelier cause than a change between releases
            call add_warning(res%warnings, &
            'identify: the '//itoa(n)//' releases disagree beyond their own '// &
            'uncertainties (chi-square p = '//sci(pool%p_value, 2)//', Birge ratio '// &
            fixed(pool%birge, 2)//'): their scatter is in u_I1 (u_I1_reproducibility = '// &
            sci(pool%u_reproducibility, 2)//'); &measurement u_period is not given, so '// &
            'each release''s u is the scatter of its own '//itoa(minval(rels%samples))// &
            ' or more timings, itself uncertain: give u_period (the u of one timed total, '// &
            's), then look for what changed between releases')
        else if (trim(pool%consistency) == 'inconsistent') then
            call add_warning(res%warnings, &
            'identify: the '//itoa(n)//' releases disagree beyond their own '// &
            'uncertainties (chi-square p = '//sci(pool%p_value, 2)//', Birge ratio '// &
            fixed(pool%birge, 2)//'): their scatter is in u_I1 (u_I1_reproducibility = '// &
            sci(pool%u_reproducibility, 2)//'); find what changed between releases')
        end if
        if (tared .and. res%i1 < 0.1_dp*res%i1_total) call add_warning(res%warnings, &
            'identify: the body''s I1 = '//sci(res%i1, 4)//' is '// &
            fixed(100.0_dp*res%i1/res%i1_total, 1)//' % of all that hung ('// &
            sci(res%i1_total, 4)//'), the rest the tare (its output '// &
            quoted(trim(d%measurement%tare))//'): its u comes mostly from the tare''s '// &
            'and from the timings of all that hung')
        if (size(m%tares) > 0 .and. res%i1 < 0.1_dp*res%i1_total) call add_warning( &
            res%warnings, 'identify: the body''s I1 = '//sci(res%i1, 4)//' is '// &
            fixed(100.0_dp*res%i1/res%i1_total, 1)//' % of all that hung ('// &
            sci(res%i1_total, 4)//'), the rest the tare ('//tare_words(m)//'): its u '// &
            'comes mostly from the tare''s and from the timings of all that hung')
        call check_physical(d, rels, res, stat)
        end associate
    end subroutine combine

    !> A release's session ('' : none given).
    pure function session_of(rel) result(s)
        type(release_t), intent(in) :: rel
        character(len=64) :: s
        s = ''
        if (allocated(rel%session)) s = rel%session
    end function session_of

    !> The sessions' results of a pooling (module pooling) into the result: their number
    !! (0 when no release names one), and with two or more each session's I1 and u, the
    !! sessions' Birge ratio and p, the sessions' part of u_I1.
    pure subroutine session_results(sp, res)
        type(sessions_pooled_t), intent(in) :: sp
        type(identify_result_t), intent(inout) :: res
        integer :: s
        res%n_sessions = 0
        if (any(sp%label /= '')) res%n_sessions = sp%n_sessions
        allocate (res%session_label(0), res%session_i1(0), res%session_u(0))
        if (sp%n_sessions < 2) return
        res%session_label = sp%label
        res%session_i1 = [(sp%within(s)%mean, s=1, sp%n_sessions)]
        res%session_u = [(sp%within(s)%u_random, s=1, sp%n_sessions)]
        res%session_birge_ratio = sp%between%birge
        res%session_p_value = sp%between%p_value
        res%session_consistency = sp%between%consistency
        res%u_i1_session = sp%u_session
    end subroutine session_results

    !> The warnings of releases pooled in sessions: the releases within the sessions that
    !! disagree; the sessions that disagree, naming the one furthest from the others.
    subroutine session_warnings(sp, res)
        type(sessions_pooled_t), intent(in) :: sp
        type(identify_result_t), intent(inout) :: res
        character(len=:), allocatable :: who
        if (trim(sp%pool%consistency) == 'inconsistent') call add_warning(res%warnings, &
            'identify: the releases within their sessions disagree beyond their own '// &
            'uncertainties (chi-square p = '//sci(sp%pool%p_value, 2)//', Birge ratio '// &
            fixed(sp%pool%birge, 2)//'): their scatter is in u_I1 (the budget''s row '// &
            'releases); find what changed between releases of a session')
        if (trim(sp%between%consistency) /= 'inconsistent') return
        who = ''
        if (sp%outlier > 0) then
            associate (s => sp%outlier)
                who = '; session '//quoted(trim(sp%label(s)))//' (I1_session = '// &
                    sci(sp%within(s)%mean, 5)//' +- '//sci(sp%within(s)%u_random, 2)//') is '// &
                    fixed(sp%outlier_z, 1)//' u from the others'' mean'
                if (sp%alone) then
                    who = who//', which agree without it: find what was different in it'
                else
                    who = who//', the furthest; the others disagree too'
                end if
            end associate
        end if
        call add_warning(res%warnings, 'identify: the '//itoa(sp%n_sessions)//' sessions '// &
            'disagree beyond their releases'' scatter (chi-square p = '// &
            sci(sp%between%p_value, 2)//', session Birge ratio '//fixed(sp%between%birge, 2)// &
            '): their scatter is in u_I1 (u_I1_session = '//sci(sp%u_session, 2)//', '// &
            itoa(sp%n_sessions - 1)//' degrees of freedom)'//who)
    end subroutine session_warnings
    !> A release's classical I1 (from its mean period at its smallest amplitude) against
    !! what the model itself gives there for this rig: the classical formula applied to the
    !! model's periods at the fitted I1 (periods: at that amplitude; a record, whose swing
    !! decays: from 1 degree, or less, up to its release amplitude).  Two-sided; refused
    !! (ERR_MODEL) only beyond LINEAR_GAP_TOL plus six times the mean period's relative u
    !! (twice, in I1), where no timing or record of this rig can be.
    subroutine check_linear_gap(d, r, stat)
        type(deck_t), intent(in) :: d
        type(release_fit_t), intent(in) :: r
        type(status_t), intent(inout) :: stat
        real(dp), parameter :: LINEAR_GAP_TOL = 0.05_dp
        real(dp) :: lo, hi, tol, tm, um, t1, t2, amin
        logical, allocatable :: sel(:)
        type(status_t) :: st
        character(len=:), allocatable :: span
        if (.not. (r%i1_linear > 0.0_dp) .or. .not. (r%i1 > 0.0_dp)) return
        tol = LINEAR_GAP_TOL
        if (.not. r%from_record) then
            if (.not. allocated(r%model_periods) .or. .not. allocated(r%amps)) return
            if (size(r%model_periods) /= size(r%amps)) return
            amin = minval(r%amps)
            sel = r%amps <= amin*(1.0_dp + 1.0e-9_dp)
            tm = sum(r%model_periods, sel)/count(sel)
            lo = linear_inertia(r%rg, tm)
            hi = lo
            if (allocated(r%u_each)) then
                if (size(r%u_each) == size(r%amps)) then
                    um = sqrt(sum(r%u_each**2, mask=sel))/count(sel)
                    tol = tol + 12.0_dp*um/tm
                end if
            end if
        else
            call rig_period_s(r%rg, accuracy_of(d), r%i1, min(1.0_dp, r%amp_max), t1, st)
            if (st%code /= 0) return
            call rig_period_s(r%rg, accuracy_of(d), r%i1, r%amp_max, t2, st)
            if (st%code /= 0) return
            lo = linear_inertia(r%rg, min(t1, t2))
            hi = linear_inertia(r%rg, max(t1, t2))
            tol = 2.0_dp*LINEAR_GAP_TOL
        end if
        if (r%i1_linear >= lo*(1.0_dp - tol) .and. r%i1_linear <= hi*(1.0_dp + tol)) return
        span = sci(lo, 4)
        if (hi > lo) span = span//' to '//sci(hi, 4)
        call set_error(stat, ERR_MODEL, 'identify: the classical formula gives I1 = '// &
            sci(r%i1_linear, 4)//' (mean period '//sci(r%period_linear, 5)//' s), where '// &
            'the model with its I1 = '//sci(r%i1, 4)//' gives it '//span// &
            ' on this rig: the periods do not follow the model''s own amplitude correction '// &
            'beyond '//itoa(nint(100.0_dp*tol))//' %; check the record''s units (t in s, '// &
            'record_units), the lengths and the release (&start amplitude, amplitudes)')
    end subroutine check_linear_gap

    !> The tares of m in words: tare_I1 = X, added_inertia = Y (those given).
    function tare_words(m) result(s)
        type(measurement_t), intent(in) :: m
        character(len=:), allocatable :: s
        integer :: k
        s = ''
        do k = 1, size(m%tares)
            if (k > 1) s = s//', '
            s = s//trim(m%tares(k)%name)//' = '//rshort(m%tares(k)%value)
        end do
    end function tare_words

    !> What no rigid body or rig can give, refused (ERR_MODEL, exit 4) with the likely
    !! cause: a release's classical I1 off what the model gives for its rig (check_linear_gap);
    !! an I1 of all that hung more than 10 % above I2 + I3 (the deck's), or
    !! 10 % below |I2 - I3|, when the deck gives inertia.  Within those margins of the
    !! triangle inequality (a lamina has I1 = I2 + I3): a warning.
    subroutine check_physical(d, rels, res, stat)
        type(deck_t), intent(in) :: d
        type(release_fit_t), intent(in) :: rels(:)
        type(identify_result_t), intent(inout) :: res
        type(status_t), intent(inout) :: stat
        real(dp) :: s23, d23, i1
        integer :: r
        i1 = res%i1_total
        call check_determined(rels, res, stat)
        if (stat%code /= 0) return
        do r = 1, size(rels)
            call check_linear_gap(d, rels(r), stat)
            if (stat%code /= 0) return
        end do
        if (.not. d%body%gave('inertia')) return
        s23 = d%body%inertia(2) + d%body%inertia(3)
        d23 = abs(d%body%inertia(2) - d%body%inertia(3))
        if (i1 > TRIANGLE_MARGIN*s23) then
            call set_error(stat, ERR_MODEL, 'identify: I1 = '//sci(i1, 4)//' is '// &
                fixed(i1/s23, 2)//' times I2 + I3 = '//sci(s23, 4)//' (&body inertia): no '// &
                'rigid body has I1 > I2 + I3; '//CAUSES_HIGH)
        else if (i1 > s23) then
            call add_warning(res%warnings, 'identify: I1 = '//sci(i1, 4)// &
                ' exceeds I2 + I3 = '//sci(s23, 4)//' by '//fixed(100.0_dp*(i1/s23 - 1.0_dp), &
                1)//' % (a lamina reaches I2 + I3, a thin rod nearly): check I2, I3 and the '// &
                'rig; '//CAUSES_HIGH)
        else if (d23 > 0.0_dp .and. i1 < d23/TRIANGLE_MARGIN) then
            call set_error(stat, ERR_MODEL, 'identify: I1 = '//sci(i1, 4)//' is below |I2 '// &
                '- I3| = '//sci(d23, 4)//' (&body inertia) by '// &
                itoa(nint(100.0_dp*(1.0_dp - i1/d23)))//' %: no rigid body has I1 < |I2 - '// &
                'I3|; '//CAUSES_LOW)
        else if (i1 < d23) then
            call add_warning(res%warnings, 'identify: I1 = '//sci(i1, 4)// &
                ' is below |I2 - I3| = '//sci(d23, 4)//': check I2, I3 and the rig; '// &
                CAUSES_LOW)
        end if
    end subroutine check_physical

    !> No fit's start value, nor a value its own u swallows, is a result: refused (ERR_DECK)
    !! when u(I1) of all that hung is not below I1 itself, naming the budget's largest row,
    !! or when a release's inversion ended at its start value (&body inertia(1)) within one
    !! iteration while the model's periods miss the measured ones.
    subroutine check_determined(rels, res, stat)
        type(release_fit_t), intent(in) :: rels(:)
        type(identify_result_t), intent(in) :: res
        type(status_t), intent(inout) :: stat
        character(len=:), allocatable :: part, who
        real(dp) :: miss
        integer :: r, j, jmax
        do r = 1, size(rels)
            if (rels(r)%from_record .or. .not. allocated(rels(r)%per)) cycle
            if (rels(r)%iterations > 1 .or. .not. (rels(r)%i1 == rels(r)%rg%inertia(1))) cycle
            miss = max(3.0_dp*maxval(rels(r)%u_each), 1.0e-9_dp*maxval(rels(r)%per))
            if (.not. (rels(r)%residual_rms > miss)) cycle
            who = ''
            if (size(rels) > 1) who = 'release '//itoa(r)//': '
            call set_error(stat, ERR_DECK, 'identify: '//who//'the inversion ended at its '// &
                'start value (&body inertia(1) = '// &
                sci(rels(r)%i1, 5)//') after '//itoa(rels(r)%iterations)//' iteration(s), '// &
                'the model''s periods off the measured ones by rms '// &
                sci(rels(r)%residual_rms, 3)//' s: the periods do not determine I1 here; '// &
                'likely: amplitudes below what the model resolves, or periods of another rig; '// &
                'allowed: periods that change with I1 on this rig')
            return
        end do
        if (res%u_i1_total < abs(res%i1_total)) return
        part = ''
        jmax = 0
        if (allocated(res%budget)) then
            do j = 1, size(res%budget)
                if (jmax == 0) then
                    jmax = j
                else if (res%budget(j)%contribution > res%budget(jmax)%contribution) then
                    jmax = j
                end if
            end do
        end if
        if (jmax > 0) then
            associate (b => res%budget(jmax))
                part = '; the largest part: '//trim(b%input)//' = '//sci(b%value, 4)// &
                    ' with u = '//sci(b%u, 3)//' (contributing '//sci(b%contribution, 3)//')'
                part = part//'; likely: a body so light on this rig that its periods '// &
                    'hardly depend on I1 (near the period with I1 -> 0), that row''s u far '// &
                    'beyond what the measurement resolves, or amplitudes below what the '// &
                    'model resolves'
            end associate
        end if
        call set_error(stat, ERR_DECK, 'identify: I1 = '//sci(res%i1_total, 5)//' with '// &
            'standard uncertainty '//sci(res%u_i1_total, 3)//' (all that hung): the '// &
            'measurement does not determine I1, its u is not below I1 itself'//part// &
            '; allowed: uncertainties and amplitudes that give u(I1) < I1')
    end subroutine check_determined

    !> One more warning line (built first: gfortran 12 fails to compile a structure
    !! constructor of such text inside an array constructor).
    subroutine add_warning(ws, msg)
        type(warning_t), allocatable, intent(inout) :: ws(:)
        character(len=*), intent(in) :: msg
        type(warning_t) :: w
        w%s = msg
        if (.not. allocated(ws)) allocate (ws(0))
        ws = [ws, w]
    end subroutine add_warning

    !> Monte Carlo of a record fit (see the module header) as a sweep (module monte_carlo):
    !! res%u_i1_mc, res%mc_mean.  The payload carries the estimate, its first-order u, s,
    !! the Jacobian, the robust weights, the parameters' sensitivities to the inputs, and
    !! the record itself with its CRC-64
    !! (record_payload): the other ranks of an MPI run take the record from it and never
    !! read the file.
    subroutine record_monte_carlo(d, r, res, stat, outdir, options, report, files)
        type(deck_t), intent(in) :: d
        type(release_fit_t), intent(in) :: r
        type(identify_result_t), intent(inout) :: res
        type(status_t), intent(out) :: stat
        character(len=*), intent(in), optional :: outdir
        type(sweep_options_t), intent(in), optional :: options
        type(sweep_report_t), intent(inout), optional :: report
        type(out_files_t), intent(in), optional :: files
        type(record_mc_task_t) :: task
        real(dp), allocatable :: payload(:), mean(:), sdev(:)
        integer :: np
        np = r%np
        payload = [crc_parts(r%crc), r%sigma*sqrt(r%tau), real(np, dp), r%p(1:np), &
                   r%u_p(1:np), reshape(r%jac, [size(r%jac)]), r%hw, &
                   reshape(r%dpdx, [size(r%dpdx)]), record_payload(r%rec)]
        call record_mc_task(rig_of(d), start_of(d), accuracy_of(d), d%measurement, r%rec, &
                            deck_inputs(d, .true.), payload, task)
        allocate (mean(np), sdev(np))
        call monte_carlo_run(task, d, d%measurement%monte_carlo, payload, mean, sdev, stat, &
                             outdir, options, report, files)
        if (stat%code /= 0) return
        res%mc_mean = mean(1) - (res%i1_total - res%i1)
        res%u_i1_mc = sqrt(sdev(1)**2 + d%measurement%u_tare_i1**2 + &
                           d%measurement%u_added_inertia**2)
    end subroutine record_monte_carlo

    !> A record as reals, last in a Monte Carlo's payload: t(n), v(n), u(n), has_u, rate,
    !! to_rad, n (n last, so that it is found from the end).
    pure function record_payload(rec) result(p)
        type(record_t), intent(in) :: rec
        real(dp), allocatable :: p(:)
        p = [rec%t, rec%v, rec%u, merge(1.0_dp, 0.0_dp, rec%has_u), &
             merge(1.0_dp, 0.0_dp, rec%rate), rec%to_rad, real(size(rec%t), dp)]
    end function record_payload

    !> The record from the end of a payload (record_payload); ok = .false. when the payload
    !! holds none.
    pure subroutine record_from_payload(p, rec, ok)
        real(dp), intent(in) :: p(:)
        type(record_t), intent(out) :: rec
        logical, intent(out) :: ok
        integer :: n, m, k
        m = size(p)
        ok = .false.
        if (m < 4) return
        if (.not. (p(m) >= 1.0_dp .and. p(m) <= real(m, dp))) return
        n = nint(p(m))
        k = m - 4 - 3*n
        if (k < 0) return
        rec%t = p(k + 1:k + n)
        rec%v = p(k + n + 1:k + 2*n)
        rec%u = p(k + 2*n + 1:k + 3*n)
        rec%has_u = p(m - 3) > 0.5_dp
        rec%rate = p(m - 2) > 0.5_dp
        rec%to_rad = p(m - 1)
        ok = .true.
    end subroutine record_from_payload

    !> The task of identify's Monte Carlo (sweep 'identify_mc') as the other ranks of an MPI
    !! run build it: from the deck (its periods) or the record rank 0 read, which travels in
    !! the payload (record_payload; the file is not read again), and the sweep's payload.
    !! ERR_DECK when the payload holds no record or its record is not rank 0's (CRC-64).
    module procedure identify_mc_task
        type(record_t) :: rec
        logical :: ok
        stat%code = 0
        if (d%measurement%n_periods > 0) then
            allocate (period_mc_task_t :: task)
            select type (task)
            type is (period_mc_task_t)
                call period_mc_task(rig_of(d), accuracy_of(d), deck_inputs(d, .false.), payload, &
                                    task)
            end select
            return
        end if
        call record_from_payload(payload, rec, ok)
        if (.not. ok) then
            call set_error(stat, ERR_DECK, '&measurement record = '''// &
                trim(d%measurement%record)//''': the Monte Carlo''s message from rank 0 '// &
                'holds no record; allowed: the same bin/bifilar_mpi on every rank')
            return
        end if
        allocate (record_mc_task_t :: task)
        select type (task)
        type is (record_mc_task_t)
            call record_mc_task(rig_of(d), start_of(d), accuracy_of(d), d%measurement, rec, &
                                deck_inputs(d, .true.), payload, task)
        end select
    end procedure identify_mc_task

    !> OUTDIR/NAME.identify: key = value lines, then the budget table of I1.
    subroutine write_identify(d, outdir, res, rels, files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(identify_result_t), intent(in) :: res
        type(release_fit_t), intent(in) :: rels(:)  !! (a record's quantity and column)
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        integer :: u, ios, j
        character(len=24) :: f(4)
        real(dp) :: rig5(5), urig5(5)
        type(rig_calibration_t) :: cal
        if (.not. all_finite([res%i1, res%u_i1, res%i1_linear, res%linear_error, &
                              res%residual_rms, res%p, res%u_p, res%u_i1_mc, res%k, &
                              res%u_i1_expanded, res%dof_eff, res%i1_total, res%u_i1_total, &
                              res%trial_i1, res%trial_u, res%budget%value, res%budget%u, &
                              res%budget%sensitivity, res%session_i1, res%session_u])) then
            call set_error(stat, ERR_NUMERIC, 'identify: a result is not finite')
            return
        end if
        if (len_trim(d%measurement%calibration) > 0) then
            call read_calibration_file(d%measurement%calibration_path, 'calibration', cal, stat)
            if (stat%code /= 0) return
        end if
        call files%open(outdir//'/'//d%name//'.identify', u, stat)
        if (stat%code /= 0) return
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar identify: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# I1 and its standard uncertainties in the '// &
            'deck''s units (mass x length^2); c_v, c_q in torque per rate (squared), '// &
            'amplitude in degrees, t0 in s, bias in rad or rad/s'
        if (ios == 0) write (u, '(a)', iostat=ios) '# b and b_prime are the full distances '// &
            'between the two cables (at the support, at the body); U_I1 = k u_I1 covers 95 %'
        if (ios == 0) write (u, '(a)', iostat=ios) '# I1_linear = m g b b_prime T^2 / '// &
            '(16 pi^2 l), l = (l + l_prime)/2, T the mean period at the smallest amplitude '// &
            '(all that hung: compare with I1_total)'
        call deck_echo(d, u, ios)
        call write_kv(u, 'I1', res%i1, ios)
        call write_kv(u, 'u_I1', res%u_i1, ios)
        call write_kv(u, 'uncertainty_given', trim(merge('yes', 'no ', res%uncertainty_given)), &
                      ios)
        call write_kv(u, 'U_I1', res%u_i1_expanded, ios)
        call write_kv(u, 'k', res%k, ios)
        if (res%dof_eff >= NU_INFINITE) then
            call write_kv(u, 'dof_eff', 'inf', ios)
        else
            call write_kv(u, 'dof_eff', res%dof_eff, ios)
        end if
        if (d%measurement%tare_i1 > 0.0_dp .or. d%measurement%added_inertia > 0.0_dp .or. &
            d%measurement%u_tare_i1 > 0.0_dp .or. d%measurement%u_added_inertia > 0.0_dp .or. &
            len_trim(d%measurement%tare) > 0) then
            call write_kv(u, 'I1_total', res%i1_total, ios)
            call write_kv(u, 'u_I1_total', res%u_i1_total, ios)
        end if
        if (len_trim(d%measurement%tare) > 0) call write_kv(u, 'I1_tare', res%i1_tare_file, ios)
        ! the body's mass: what hung (each release's mass, a table's column or &body mass)
        ! less the fixture's
        if (d%measurement%tare_mass > 0.0_dp .and. size(rels) > 0) &
            call write_kv(u, 'mass_body', sum(rels%rg%mass)/size(rels) - &
                          d%measurement%tare_mass, ios)
        if (d%measurement%monte_carlo > 0) call write_kv(u, 'u_I1_monte_carlo', res%u_i1_mc, ios)
        call write_kv(u, 'I1_linear', res%i1_linear, ios)
        call write_kv(u, 'linear_error', res%linear_error, ios)
        do j = 2, res%np
            call write_kv(u, trim(res%names(j)), res%p(j), ios)
            call write_kv(u, 'u_'//trim(res%names(j)), res%u_p(j), ios)
        end do
        if (res%determined) then
            ! what the record determines: each u against its prior u (none: no prior), the
            ! parameters' largest correlation and the condition number of the fit
            do j = 1, res%np
                if (res%u_prior(j) > 0.0_dp) then
                    call write_kv(u, 'u_prior_'//trim(res%names(j)), res%u_prior(j), ios)
                else
                    call write_kv(u, 'u_prior_'//trim(res%names(j)), 'none', ios)
                end if
            end do
            call write_kv(u, 'correlation_max', res%correlation_max, ios)
            if (len_trim(res%correlation_pair) > 0) &
                call write_kv(u, 'correlation_pair', trim(res%correlation_pair), ios)
            call write_kv(u, 'condition', res%condition, ios)
        end if
        call write_kv(u, 'n_trials', res%n_trials, ios)
        if (trim(d%measurement%on_failure) == 'skip') then
            call write_kv(u, 'n_trials_skipped', res%n_trials_skipped, ios)
            do j = 1, size(res%skipped)
                call write_kv(u, 'trial_skipped('//itoa(j)//')', res%skipped(j)%s, ios)
            end do
        end if
        if (res%n_trials == 1 .and. any(res%trial_session /= '')) &
            call write_kv(u, 'session', trim(res%trial_session(1)), ios)
        if (res%n_sessions > 0) call write_kv(u, 'n_sessions', res%n_sessions, ios)
        if (res%n_sessions >= 2) then
            if (res%session_birge_ratio >= 0.0_dp) then
                call write_kv(u, 'session_birge_ratio', res%session_birge_ratio, ios)
                call write_kv(u, 'session_p_value', res%session_p_value, ios)
            end if
            call write_kv(u, 'session_consistency', trim(res%session_consistency), ios)
            call write_kv(u, 'u_I1_session', res%u_i1_session, ios)
            do j = 1, res%n_sessions
                call write_kv(u, 'session_label('//itoa(j)//')', trim(res%session_label(j)), ios)
                call write_kv(u, 'I1_session('//itoa(j)//')', res%session_i1(j), ios)
                call write_kv(u, 'u_I1_session('//itoa(j)//')', res%session_u(j), ios)
            end do
        end if
        call write_kv(u, 'consistency', trim(res%consistency), ios)
        call write_kv(u, 'u_I1_reproducibility', res%u_i1_reproducibility, ios)
        if (res%birge_ratio >= 0.0_dp) then
            call write_kv(u, 'birge_ratio', res%birge_ratio, ios)
            call write_kv(u, 'consistency_p_value', res%p_value, ios)
        end if
        call write_kv(u, 'fit_consistency', trim(res%fit_consistency), ios)
        if (res%fit_birge_ratio >= 0.0_dp) call write_kv(u, 'fit_birge_ratio', &
                                                         res%fit_birge_ratio, ios)
        call write_kv(u, 'period_model', trim(res%period_model), ios)
        call write_kv(u, 'residual_rms', res%residual_rms, ios)
        call write_kv(u, 'iterations', res%iterations, ios)
        call write_kv(u, 'cpu_seconds', res%cpu_seconds, ios)
        if (res%from_record) then
            call write_kv(u, 'mode', 'record', ios)
            if (res%n_trials == 1 .and. size(res%record_crc) == 1) &
                call write_kv(u, 'record_crc64', hex16(res%record_crc(1)), ios)
            ! the record's: the deck's quantity, or the unit its column's name says
            if (allocated(rels(1)%rec%vs) .and. trim(d%measurement%quantity) == 'point') then
                call write_kv(u, 'quantity', 'point', ios)
                call write_kv(u, 'record_view', trim(d%measurement%record_view), ios)
            else if (allocated(rels(1)%rec%vs)) then
                call write_kv(u, 'quantity', 'rates', ios)
                call write_kv(u, 'record_axes', trim(d%measurement%record_axes), ios)
            else
                call write_kv(u, 'quantity', trim(merge('rate ', 'angle', rels(1)%rec%rate)), ios)
            end if
            if (rels(1)%rec%axis_chosen) call write_kv(u, 'record_axis', &
                trim(rels(1)%rec%value_name)//' (the axis with the largest swing)', ios)
            call write_kv(u, 'samples', res%samples, ios)
            if (res%n_trials == 1) then
                call write_kv(u, 'sigma', res%sigma, ios)
                call write_kv(u, 'sigma_source', trim(merge('stated   ', 'residuals', &
                                                            res%sigma_stated)), ios)
                call write_kv(u, 'residual_correlation_time', res%correlation_time, ios)
                call write_kv(u, 'n_effective', res%n_effective, ios)
                call write_kv(u, 'u_I1_fit', res%u_i1_fit, ios)
                call write_kv(u, 'mean_period', res%period_linear, ios)
            end if
            call write_kv(u, 'model_evaluations', res%evaluations, ios)
        else
            call write_kv(u, 'mode', 'periods', ios)
            if (res%n_trials == 1) then
                do j = 1, size(res%model_periods)
                    call write_kv(u, 'model_period('//itoa(j)//')', res%model_periods(j), ios)
                end do
                call write_kv(u, 'linear_period', res%period_linear, ios)
                if (res%u_period_scatter >= 0.0_dp) &
                    call write_kv(u, 'u_period_from_scatter', res%u_period_scatter, ios)
            end if
        end if
        if (res%n_trials > 1) then
            do j = 1, res%n_trials
                call write_kv(u, 'trial('//itoa(j)//')', trim(res%trial_label(j)), ios)
                if (any(res%trial_session /= '')) call write_kv(u, 'session('//itoa(j)//')', &
                    trim(res%trial_session(j)), ios)
                call write_kv(u, 'I1_trial('//itoa(j)//')', res%trial_i1(j), ios)
                call write_kv(u, 'u_I1_trial('//itoa(j)//')', res%trial_u(j), ios)
                if (res%from_record .and. size(res%record_crc) >= j) call write_kv(u, &
                    'record_crc64('//itoa(j)//')', hex16(res%record_crc(j)), ios)
            end do
        end if
        if (d%measurement%monte_carlo > 0) then
            call write_kv(u, 'monte_carlo_samples', d%measurement%monte_carlo, ios)
            call write_kv(u, 'monte_carlo_seed', d%measurement%seed, ios)
            call write_kv(u, 'I1_monte_carlo_mean', res%mc_mean, ios)
        end if
        call write_kv(u, 'warnings', size(res%warnings), ios)
        ! what a deck that takes this output as its tare (&measurement tare) reads: the part
        ! measured anew (the budget's first budget_own_rows rows) with its dof, the rig
        call write_kv(u, 'u_I1_own', res%u_i1_own, ios)
        if (res%dof_own >= NU_INFINITE) then
            call write_kv(u, 'dof_own', 'inf', ios)
        else
            call write_kv(u, 'dof_own', res%dof_own, ios)
        end if
        call write_kv(u, 'budget_own_rows', res%n_own_rows, ios)
        rig5 = [d%suspension%l, d%suspension%l_prime, d%suspension%b, d%suspension%b_prime, &
                d%suspension%g]
        urig5 = [d%measurement%u_l, d%measurement%u_l_prime, d%measurement%u_b, &
                 d%measurement%u_b_prime, d%measurement%u_g]
        do j = 1, 5
            call write_kv(u, 'rig_'//trim(RIG_KEYS(j)), rig5(j), ios)
            call write_kv(u, 'u_rig_'//trim(RIG_KEYS(j)), urig5(j), ios)
        end do
        if (len_trim(d%measurement%calibration) > 0) then
            call write_kv(u, 'calibration_delta_l', cal%delta_l, ios)
            call write_kv(u, 'calibration_scale', cal%scale, ios)
        end if
        if (ios == 0) write (u, '(a)', iostat=ios) '# budget of I1 (first order, GUM): input '// &
            'value u sensitivity contribution (contribution = |sensitivity| u; u_I1 is '// &
            'their root sum of squares)'
        do j = 1, size(res%budget)
            call es_field(res%budget(j)%value, 15, f(1))
            call es_field(res%budget(j)%u, 15, f(2))
            call es_field(res%budget(j)%sensitivity, 15, f(3))
            call es_field(res%budget(j)%contribution, 15, f(4))
            ! a label longer than its column (amplitude_scale) pushes the fields, whole
            if (ios == 0) write (u, '(a)', iostat=ios) res%budget(j)%input(1:max(14, &
                merge(len_trim(res%budget(j)%input) + 1, 0, &
                      len_trim(res%budget(j)%input) > 14)))//f(1)//f(2)// &
                f(3)//f(4)
        end do
        call files%close(u, ios, stat)
    end subroutine write_identify

    !> OUTDIR/NAME.fit.dat: t measured model residual in the record's units, one block
    !! (two blank lines between) per release, from its first sample fitted.
    subroutine write_fit(d, outdir, rels, files, stat, fig)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(release_fit_t), intent(in) :: rels(:)
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        type(cert_figure_data_t), intent(inout) :: fig     !! the certificate's: release 1
        integer :: u, ios, i, r, i0
        character(len=96) :: row
        character(len=:), allocatable :: unit_name
        real(dp) :: s
        call files%open(outdir//'/'//d%name//'.fit.dat', u, stat)
        if (stat%code /= 0) return
        unit_name = trim(merge('W     ', 'theta4', rels(1)%rec%rate))//' ('// &
            trim(rels(1)%rec%units)//')'
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar identify fit: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# t in s as recorded; measured, model '// &
            'and residual (measured - model) are '//unit_name//'; one block per release'
        if (ios == 0) write (u, '(a)', iostat=ios) '# quantity: '//unit_name
        call deck_echo(d, u, ios)
        if (ios == 0) write (u, '(a)', iostat=ios) '# t measured model residual'
        do r = 1, size(rels)
            if (r > 1 .and. ios == 0) write (u, '(/)', iostat=ios)
            s = 1.0_dp/rels(r)%rec%to_rad
            i0 = rels(r)%ifirst
            do i = i0, i0 + size(rels(r)%model) - 1
                call es_field(rels(r)%rec%t(i), 15, row(1:24))
                call es_field(s*rels(r)%rec%v(i), 15, row(25:48))
                call es_field(s*rels(r)%model(i - i0 + 1), 15, row(49:72))
                call es_field(s*(rels(r)%rec%v(i) - rels(r)%model(i - i0 + 1)), 15, row(73:96))
                if (ios == 0) write (u, '(a)', iostat=ios) row
            end do
        end do
        call files%close(u, ios, stat)
        s = 1.0_dp/rels(1)%rec%to_rad
        i0 = rels(1)%ifirst
        fig%record = .true.
        fig%units = unit_name
        fig%t = rels(1)%rec%t(i0:i0 + size(rels(1)%model) - 1)
        fig%measured = s*rels(1)%rec%v(i0:i0 + size(rels(1)%model) - 1)
        fig%model = s*rels(1)%model
    end subroutine write_fit

    !> OUTDIR/NAME.periods.dat, the figure of periods against amplitude.  Block 0, the
    !! timed periods: release, amplitude (deg), period per cycle (s), its u, the model's
    !! period at I1_total.  Then one block per rig: amplitude, the model's period at
    !! I1_total, the classical formula's (independent of amplitude), 41 amplitudes from 0 to
    !! 1.1 times the largest timed (at most 179 deg; 11 on an elastic platform off its
    !! axis).  Computed whole before the file opens.
    subroutine write_periods(d, outdir, rels, res, files, stat, fig)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(release_fit_t), intent(in) :: rels(:)
        type(identify_result_t), intent(in) :: res
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        !> the certificate's: every timed period, the curve of the first release's rig
        type(cert_figure_data_t), intent(inout) :: fig
        integer, parameter :: NA = 41, NA_ELASTIC = 11
        integer :: u, ios, i, r, q, k, na_of(size(rels))
        character(len=104) :: row
        real(dp) :: amax, tcl(size(rels)), curve(NA, 2, size(rels))
        logical :: first(size(rels))
        type(release_fit_t), allocatable :: tm(:)
        amax = 0.0_dp
        do r = 1, size(rels)
            amax = max(amax, maxval(rels(r)%amps))
        end do
        amax = min(179.0_dp, 1.1_dp*amax)
        ! the model's periods at the timed amplitudes, and the curves of each rig
        allocate (tm(size(rels)))
        do r = 1, size(rels)
            allocate (tm(r)%per(size(rels(r)%per)))
            do i = 1, size(rels(r)%per)
                call rig_period_s(rels(r)%rg, accuracy_of(d), res%i1_total, rels(r)%amps(i), &
                                  tm(r)%per(i), stat, rels(r)%cycles(i))
                if (stat%code /= 0) exit
            end do
            first(r) = .true.
            do q = 1, r - 1
                if (same_rig(rels(q)%rg, rels(r)%rg)) first(r) = .false.
            end do
            if (.not. first(r) .or. stat%code /= 0) cycle
            associate (g => rels(r)%rg)
                tcl(r) = 4.0_dp*pi*sqrt(res%i1_total*0.5_dp*(g%l + g%l_prime)/ &
                                        (g%mass*g%g*g%b*g%b_prime))
            end associate
            ! four or more cables off the axis: each period a whole elastic simulation
            na_of(r) = merge(NA_ELASTIC, NA, offaxis_platform(rels(r)%rg) .and. &
                             rels(r)%rg%cables >= 4)
            do k = 1, na_of(r)
                curve(k, 1, r) = max(0.25_dp, amax*(k - 1)/real(na_of(r) - 1, dp))
                call rig_period_s(rels(r)%rg, accuracy_of(d), res%i1_total, curve(k, 1, r), &
                                  curve(k, 2, r), stat)
                if (stat%code /= 0) exit
            end do
        end do
        if (stat%code /= 0) then
            stat%msg = 'identify, the model''s periods of the figure: '//stat%msg
            return
        end if
        call files%open(outdir//'/'//d%name//'.periods.dat', u, stat)
        if (stat%code /= 0) return
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar identify periods: '//trim(d%scene%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# block 0: release amplitude(deg) '// &
            'period(s, per cycle) u_period model_period; then one block per rig: '// &
            'amplitude(deg) model_period classical_period (the model at I1_total = '// &
            trim(sci(res%i1_total, 6))//')'
        call deck_echo(d, u, ios)
        do r = 1, size(rels)
            do i = 1, size(rels(r)%per)
                write (row(1:8), '(i8)') r
                call es_field(rels(r)%amps(i), 15, row(9:32))
                call es_field(rels(r)%per(i), 15, row(33:56))
                call es_field(rels(r)%u_each(i), 15, row(57:80))
                call es_field(tm(r)%per(i), 15, row(81:104))
                if (ios == 0) write (u, '(a)', iostat=ios) row
            end do
        end do
        do r = 1, size(rels)
            if (.not. first(r)) cycle
            if (ios == 0) write (u, '(/)', iostat=ios)
            do k = 1, na_of(r)
                call es_field(curve(k, 1, r), 15, row(1:24))
                call es_field(curve(k, 2, r), 15, row(25:48))
                call es_field(tcl(r), 15, row(49:72))
                if (ios == 0) write (u, '(a)', iostat=ios) row(1:72)
            end do
        end do
        call files%close(u, ios, stat)
        fig%periods = .true.
        allocate (fig%amp(0), fig%per(0), fig%u_per(0))
        do r = 1, size(rels)
            fig%amp = [fig%amp, rels(r)%amps]
            fig%per = [fig%per, rels(r)%per]
            fig%u_per = [fig%u_per, rels(r)%u_each]
        end do
        fig%curve_amp = curve(1:na_of(1), 1, 1)
        fig%curve_per = curve(1:na_of(1), 2, 1)
        fig%classical = tcl(1)
    contains
        pure logical function same_rig(a1, a2)
            type(rig_t), intent(in) :: a1, a2
            same_rig = a1%l == a2%l .and. a1%l_prime == a2%l_prime .and. a1%b == a2%b .and. &
                       a1%b_prime == a2%b_prime .and. a1%mass == a2%mass
        end function same_rig
    end subroutine write_periods

    ! ------------------------------------------------------------ the analysis for the driver

    !> The preconditions (identify_ready), what they read kept for the run.
    module procedure identify_analysis_ready
        call identify_ready(d, stat, self%input)
    end procedure identify_analysis_ready

    !> The run (run_identify into the run's files, from what ready read); the Monte Carlo's
    !! warning and the result's warnings kept.
    module procedure identify_analysis_run
        integer :: k
        call run_identify(d, outdir, self%res, stat, files, options, self%rep, self%input)
        call self%add_report_warning(self%rep)
        if (stat%code /= 0) return
        do k = 1, size(self%res%warnings)
            call self%add_warning(self%res%warnings(k)%s)
        end do
    end procedure identify_analysis_run

    !> ' identify I1 = ... ± U (k = K, 95 %)..., N iterations;'
    module procedure identify_summary
        integer :: k
        associate (idr => self%res, rep => self%rep)
            if (idr%uncertainty_given) then
                s = ' identify I1 = '//sci(idr%i1, 5)//' ± '// &
                    sci(idr%u_i1_expanded, 2)//' (k = '//fixed(idr%k, 1)//', 95 %)'
            else
                s = ' identify I1 = '//sci(idr%i1, 5)//' (no uncertainty '// &
                    'given: every u_* of &measurement is 0)'
            end if
            do k = 2, idr%np
                if (idr%names(k) == 'c_v' .or. idr%names(k) == 'c_q') s = s// &
                    ', '//trim(idr%names(k))//' = '//sci(idr%p(k), 3)//' ± '// &
                    sci(idr%k*idr%u_p(k), 2)
            end do
            if (idr%n_trials > 1) s = s//', '//itoa(idr%n_trials)//' releases '// &
                trim(idr%consistency)
            s = s//', period model '//trim(idr%period_model)
            if (allocated(self%input%m%obs)) then
                ! the first record's axis, when the program chose it (a gyro export)
                k = findloc(self%input%m%obs%kind, OBS_RECORD, 1)
                if (k > 0) then
                    if (self%input%m%obs(k)%have_record) &
                        s = s//chosen_axis_note(self%input%m%obs(k)%rec)
                end if
            end if
            if (idr%u_i1_mc >= 0.0_dp) then
                s = s//' (Monte Carlo u '//sci(idr%u_i1_mc, 2)//' from '// &
                    itoa(d%measurement%monte_carlo)//' samples, '// &
                    fixed(rep%wall_seconds, 2)//' s'//ranks_note(rep)//resume_note(rep)//')'
            end if
            if (idr%i1_linear > 0.0_dp .and. idr%i1_total /= idr%i1) then
                ! a tare or an added inertia: the formula sees all that hung, and is
                ! compared with what the rig measured of it, not with the body's I1
                s = s//', linear formula of all that hung '//sci(idr%i1_linear, 5)//' ('// &
                    trim(merge('+', ' ', idr%linear_error >= 0.0_dp))// &
                    fixed(100.0_dp*idr%linear_error, 2)//' % against I1_total = '// &
                    sci(idr%i1_total, 5)//')'
            else if (idr%i1_linear > 0.0_dp) then
                s = s//', linear formula '//sci(idr%i1_linear, 5)//' ('// &
                    trim(merge('+', ' ', idr%linear_error >= 0.0_dp))// &
                    fixed(100.0_dp*idr%linear_error, 2)//' %)'
            else
                s = s//', no period in the record for the linear formula'
            end if
            s = s//', '//itoa(idr%iterations)//' iterations;'
        end associate
    end procedure identify_summary

    !> The task of its Monte Carlo on the other ranks of an MPI run (identify_mc_task).
    module procedure identify_sweep_task
        call unused(self)
        call unused(sweep)
        call identify_mc_task(d, payload, task, stat)
    end procedure identify_sweep_task

end submodule identify_impl
