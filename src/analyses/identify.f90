!> The moment of inertia I1 from what was measured (analysis identify): measured periods
!! or a recorded swing, with damping and an uncertainty budget.
!!
!! * Periods (&measurement periods, amplitudes): module period_inversion.  I1 by weighted
!!   least squares from the exact period of pure torsion (eqs. (45)-(49)) on a symmetric
!!   rig, or from the full model's period on any other (simulated_period_s); first-order
!!   budget by central differences of the whole inversion; Monte Carlo by re-inverting with
!!   every input drawn from its normal distribution.  Without u_period, two periods or more
!!   give it as their scatter about the model (s^2 = sum of squares over n - 1), and the
!!   inversion, budget and Monte Carlo use that.
!! * A record (&measurement record): time (s) and theta4 (rad, quantity = 'angle') or
!!   W = omega . n3 (rad/s, quantity = 'rate'), optionally each sample's standard
!!   uncertainty.  The full nonlinear model (unequal cables, offset mass centre, tilting and
!!   sway as they come, the damping torque of &damping) is started from the deck's &start
!!   at t = t0 (the record's time of release, 0 unless estimated; a sample before t0 sees
!!   the body held at the start) and run in memory through the run loop (module run_loop)
!!   to the record's last sample; its value at the sample times is compared with the
!!   record.  The parameters of &measurement estimate (I1 and any of c_v, c_q, amplitude,
!!   t0) minimise sum ((model - measured)/u_i)^2 (u_i = 1 without column 3) by
!!   Levenberg-Marquardt (module least_squares), with forward differences of the model.
!!   An oscillation's phase makes the misfit many-valued in I1 over a long record, so the
!!   fit runs first on about two periods of the record (its mean period from the zero
!!   crossings), then on windows twice as long, each from the last estimate, up to the
!!   whole record.
!! * First-order uncertainty (GUM, JCGM 100:2008): the fit's covariance
!!   C = s^2 (J^T W J)^-1, J by central differences at the estimate, s = 1 when the record
!!   gives each sample's uncertainty (column 3: 'stated'), else s^2 = the residuals' sum of
!!   squares over (samples - parameters) ('residuals'); plus each stated input uncertainty
!!   (mass, l, l_prime, b, b_prime, g, and the start amplitude when it is held) times the
!!   estimate's sensitivity to that input, by the implicit-function form
!!   dp/dx = -(J^T W J)^-1 J^T W dr/dx (to first order the refit's change; dr/dx by central
!!   differences, two model runs per input).  u_P^2 = C_PP + sum_x (dP/dx u_x)^2.  The
!!   period's uncertainty u_period is not an input of a record fit (the record's noise is
!!   in the residuals or column 3).
!! * Monte Carlo (GUM Supplement 1, JCGM 101:2008), monte_carlo = N samples: sample k draws,
!!   from stream k of the seed (module random), every input from N(x, u_x^2) (the order
!!   mass, l, l_prime, b, b_prime, g, amplitude) and then every measured value from
!!   N(v_i, s_i^2) (s_i the stated u_i or s), and refits from the estimate: Gauss-Newton
!!   with the estimate's Jacobian (each step one model run) until the step is below 1e-3 of
!!   each parameter's first-order u, else Levenberg-Marquardt.  u_I1_monte_carlo is the
!!   samples' standard deviation.  A sample depends only on (seed, k): any order, thread or
!!   rank gives the same numbers.  The samples (of periods too) are a sweep (module
!!   monte_carlo) over the OpenMP threads and the MPI ranks, checkpointed to
!!   OUTDIR/NAME.identify_mc.partial and resumed with --resume; the other ranks build the
!!   task from the deck and the payload rank 0 sends (identify_mc_task).
!! * The classical value beside it: I1_linear = m g b b' T^2 / (16 pi^2 l) (l the mean of
!!   the two cable lengths), T the period at the smallest amplitude or the record's mean
!!   period; linear_error = I1_linear / I1 - 1.
!!
!! Files: OUTDIR/NAME.identify (key = value lines, then the budget table of I1); with a
!! record also OUTDIR/NAME.fit.dat (t, measured, model, residual).  No routine stops.
module identify
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_usual
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp, pi
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_NUMERIC, ERR_IO
    use text, only: itoa, sci
    use deck, only: deck_t, deck_echo, estimated, count_words, TAU_END_MAX, traps_off, &
                    traps_restore, read_line
    use output_io, only: out_files_t, write_kv, all_finite
    use fast_format, only: es_field
    use geometry, only: pendulum_t
    use bifilar_model, only: NSTATE, motion_t, motion_parts_t, evaluate
    use simulate, only: make_pendulum, start_state, kane_run_start, kane_run_t, integrator_of
    use run_loop, only: stepped_model_t, row_sink_t, drive
    use least_squares, only: lsq_problem_t, lsq_options_t, lsq_result_t, lm_fit, lsq_jacobian
    use lapack_wrap, only: la_lstsq, la_svd
    use random, only: rng_t, rng_stream, rng_normal
    use period_inversion, only: input_u_t, period_fit_t, budget_row_t, invert_periods, &
                                period_budget, period_monte_carlo, linear_inertia, &
                                move_b_prime, is_torsion_rig, rig_period_s, period_mc_task, &
                                period_mc_task_t
    use sweep_engine, only: sweep_task_t, sweep_options_t, sweep_report_t
    use crc64, only: file_crc, crc_parts, crc_join
    use monte_carlo, only: mc_task_t, monte_carlo_run
    implicit none
    private

    !> A record: time from release (s), the measured value (rad or rad/s) and, when the
    !! record has a third column, each sample's standard uncertainty.
    type, public :: record_t
        real(dp), allocatable :: t(:), v(:), u(:)
        logical :: has_u = .false.
    end type record_t

    !> What identify found (deck units; the record's units for residuals).
    type, public :: identify_result_t
        logical :: from_record = .false.        !! a record fit (else periods)
        real(dp) :: i1 = 0.0_dp, u_i1 = 0.0_dp  !! estimate and first-order u
        real(dp) :: u_i1_fit = 0.0_dp           !! the fit's part of u_I1 (record)
        real(dp) :: u_i1_mc = -1.0_dp, mc_mean = 0.0_dp     !! Monte Carlo (when asked)
        real(dp) :: i1_linear = 0.0_dp, linear_error = 0.0_dp
        real(dp) :: period_linear = 0.0_dp      !! the period the linear formula used (s)
        !> periods without u_period: their scatter about the model, s (used as u_period;
        !! -1 when u_period is given or there is one period)
        real(dp) :: u_period_scatter = -1.0_dp
        real(dp) :: residual_rms = 0.0_dp       !! of measured - model (s, rad or rad/s)
        integer :: iterations = 0, evaluations = 0, samples = 0
        integer :: np = 0                       !! parameters estimated
        character(len=9) :: names(5) = ''       !! their names (I1 first)
        real(dp) :: p(5) = 0.0_dp, u_p(5) = 0.0_dp  !! estimates and first-order u
        real(dp) :: sigma = 0.0_dp              !! s of the covariance (record)
        logical :: sigma_stated = .false.       !! s = 1: the record's column 3
        real(dp), allocatable :: model_periods(:)   !! T_i(I1) (periods)
        logical :: periods_exact = .true.       !! periods of pure torsion (else simulated)
        type(budget_row_t), allocatable :: budget(:)
        real(dp), allocatable :: model(:)       !! the model at the record's times
        real(dp) :: cpu_seconds = 0.0_dp
    end type identify_result_t

    !> Parameters a record fit can estimate (deck ESTIMATES_ALLOWED), in this order.
    integer, parameter :: P_I1 = 1, P_CV = 2, P_CQ = 3, P_AMP = 4, P_T0 = 5
    character(len=9), parameter :: PARAM_NAMES(5) = [character(len=9) :: 'I1', 'c_v', 'c_q', &
        'amplitude', 't0']

    !> The record fit as a least-squares problem: residuals ((model - measured)/u_i) over the
    !! first nuse samples.
    type, extends(lsq_problem_t) :: record_fit_t
        type(deck_t) :: d                       !! the rig, every held value (inputs)
        type(record_t) :: rec                   !! the record (values perturbed by Monte Carlo)
        integer :: np = 0                       !! parameters estimated
        integer :: which(5) = 0                 !! P_* of each estimated parameter
        real(dp) :: t0 = 0.0_dp                 !! release time (s), when held
        logical :: rate = .false.               !! quantity = 'rate'
        integer :: nuse = 0                     !! samples fitted (the window)
        real(dp), allocatable :: w(:)           !! 1/u_i (1 without column 3)
    contains
        procedure :: residual => record_residual
    end type record_fit_t

    !> The model's value at the record's sample times (a sink of the run loop).
    type, extends(row_sink_t) :: record_sink_t
        logical :: rate = .false.
        type(pendulum_t) :: p                   !! for W = omega . n3
        real(dp), allocatable :: vals(:)        !! theta4 (rad) or W (rad per unit tau)
    contains
        procedure :: take => record_take
    end type record_sink_t

    !> The samples of a record fit's Monte Carlo (record_mc_point) as a sweep: the fit
    !! problem, the estimate the samples start from, its Jacobian and first-order u, s, and
    !! the inputs drawn; built by record_mc_task from the deck, the record and the payload.
    type, extends(mc_task_t) :: record_mc_task_t
        type(record_fit_t) :: prob              !! the fit (deck, record, weights)
        real(dp), allocatable :: phat(:)        !! the estimate
        real(dp), allocatable :: jac(:, :)      !! the Jacobian there (samples, parameters)
        real(dp), allocatable :: u_p(:)         !! first-order u of each parameter
        real(dp) :: sigma = 0.0_dp              !! s of the covariance
        real(dp), allocatable :: xval(:), ux(:) !! the inputs drawn: values, u
    contains
        procedure :: sample => record_mc_point
    end type record_mc_task_t

    public :: identify_ready, run_identify, read_record, record_model, make_record
    public :: identify_mc_task
    public :: fit_record, mean_period, identify_record, set_input

    integer, parameter :: MIN_SAMPLES = 20          !! shortest record
    integer, parameter :: MAX_SAMPLES = 2000000     !! longest record
    integer, parameter :: MAX_RECORD_LINE = 4096    !! longest line of a record
    !> Largest recorded value: rad (angle) or rad per unit of tau (rate, W/sqrt(g/b')); a
    !! standard uncertainty (column 3) from U_MIN to VALUE_MAX in the same units (a smaller
    !! one makes weights 1/u that overflow the fit's sum of squares).
    real(dp), parameter :: VALUE_MAX = 1.0e3_dp, U_MIN = 1.0e-12_dp
    real(dp), parameter :: H_REL = 1.0e-5_dp        !! relative difference step of the model
    real(dp), parameter :: DAMP_REF = 1.0e-3_dp     !! scale of c_v, c_q (model's units)
    real(dp), parameter :: COND_MAX = 1.0e10_dp     !! largest condition number of J (scaled)

contains

    ! ------------------------------------------------------------------ preconditions

    !> The preconditions of analyses = 'identify', checked before any computing: the
    !! paper's model; periods or a record, not both; with periods only I1 estimated and the
    !! periods possible on a symmetric rig (T(I1 -> 0) below each); with a record, the
    !! record readable and sound (read_record), I1 among the estimated parameters,
    !! 'amplitude' only with &start mode 'raised', more samples than parameters, the start.
    subroutine identify_ready(d, stat)
        type(deck_t), intent(in) :: d           !! the deck
        type(status_t), intent(out) :: stat     !! ERR_DECK
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
        call make_pendulum(d, p, stat)
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
            if (is_torsion_rig(d)) then
                ! a period no positive I1 gives: refused now (cheap on a symmetric rig)
                call invert_periods(d, d%periods(1:d%n_periods), d%amplitudes(1:d%n_periods), &
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
        call start_state(d, p, y0, th0, stat)
    end subroutine identify_ready

    ! ------------------------------------------------------------------ the record

    !> Read and check the record of a deck (d%record_path): a whitespace table, '#' starts
    !! a comment, blank lines skipped; column 1 time (s) strictly increasing, column 2 the
    !! measured value (|value| <= VALUE_MAX rad, or VALUE_MAX sqrt(g/b') rad/s for a rate),
    !! an optional column 3 its standard uncertainty (U_MIN ... VALUE_MAX in those units);
    !! every data line with the same number of columns, every value finite; at least
    !! MIN_SAMPLES samples.  Numbers beyond the range of real(dp) (1e400) are read with the
    !! floating-point traps off and refused as not finite.  ERR_DECK naming the record, the
    !! line, what is wrong and what is allowed.
    subroutine read_record(d, rec, stat)
        type(deck_t), intent(in) :: d           !! the deck (record, record_path)
        type(record_t), intent(out) :: rec
        type(status_t), intent(out) :: stat     !! ERR_DECK
        character(len=MAX_RECORD_LINE + 1) :: line
        character(len=512) :: msg
        character(len=:), allocatable :: head, path, whole
        real(dp) :: x(3), scale
        real(dp), allocatable :: t(:), v(:), uu(:)
        integer :: u, ios, nline, ncol, n, k, ncol1
        logical :: halting(size(ieee_usual))
        character(len=:), allocatable :: units, per_tau
        stat%code = 0
        head = '&measurement record = '''//trim(d%record)//''': '
        scale = 1.0_dp
        units = ' rad'
        per_tau = ''
        if (trim(d%quantity) == 'rate') then
            scale = sqrt(d%g/d%b_prime)
            units = ' rad/s'
            per_tau = ' (= '//sci(VALUE_MAX)//' sqrt(g/b_prime))'
        end if
        path = record_file(d)
        open (newunit=u, file=path, status='old', action='read', form='formatted', &
              access='sequential', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_DECK, head//'cannot open '//path//': '// &
                trim(msg)//'; allowed: a file relative to the deck''s folder, or an absolute path')
            return
        end if
        allocate (t(1024), v(1024), uu(1024))
        n = 0
        nline = 0
        ncol1 = 0
        call traps_off(halting)
        do
            ! a line of any length is read only up to MAX_RECORD_LINE + 1 characters (a file
            ! without line ends, /dev/zero, ends at once)
            call read_line(u, whole, ios, msg, MAX_RECORD_LINE)
            if (is_iostat_end(ios)) exit
            nline = nline + 1
            if (ios /= 0) then
                call fail('cannot read line '//itoa(nline)//': '//trim(msg))
                return
            end if
            ! the whole text read, blanks included: a longer line is cut where read_line
            ! stopped, and its rest would be read as the next line
            if (len(whole) > MAX_RECORD_LINE) then
                call fail('line '//itoa(nline)//' is longer than '//itoa(MAX_RECORD_LINE)// &
                    ' characters; allowed: lines of at most '//itoa(MAX_RECORD_LINE))
                return
            end if
            line = whole
            k = index(line, '#')
            if (k > 0) line(k:) = ' '
            call split(line, x, ncol, msg)
            if (len_trim(msg) > 0) then
                call fail('line '//itoa(nline)//': '//trim(msg))
                return
            end if
            if (ncol == 0) cycle
            if (ncol1 == 0) ncol1 = ncol
            if (ncol < 2 .or. ncol > 3 .or. ncol /= ncol1) then
                call fail('line '//itoa(nline)//': '//itoa(ncol)//' columns; allowed: every '// &
                    'line with 2 columns (time in s, value) or every line with 3 (and its '// &
                    'standard uncertainty)')
                return
            end if
            if (.not. all(ieee_is_finite(x(1:ncol)))) then
                call fail('line '//itoa(nline)//': a value is not a finite number (NaN, Inf); '// &
                    'allowed: finite numbers')
                return
            end if
            if (n > 0) then
                if (.not. (x(1) > t(n))) then
                    call fail('line '//itoa(nline)//': time '//sci(x(1), 6)// &
                        ' s is not after the previous sample''s '//sci(t(n), 6)// &
                        ' s; allowed: column 1 strictly increasing (s from release)')
                    return
                end if
            end if
            if (abs(x(2)) > VALUE_MAX*scale) then
                call fail('line '//itoa(nline)//': value '//sci(x(2))//' is too large; '// &
                    'allowed: |value| <= '//sci(VALUE_MAX*scale)//units//per_tau)
                return
            end if
            if (ncol == 3) then
                if (.not. (x(3) >= U_MIN*scale .and. x(3) <= VALUE_MAX*scale)) then
                    call fail('line '//itoa(nline)//': standard uncertainty '//sci(x(3))// &
                        ' is out of range; allowed: column 3 from '//sci(U_MIN*scale)// &
                        ' to '//sci(VALUE_MAX*scale)//units)
                    return
                end if
            end if
            if (n == MAX_SAMPLES) then
                call fail('more than '//itoa(MAX_SAMPLES)//' samples; allowed: at most '// &
                    itoa(MAX_SAMPLES))
                return
            end if
            if (n == size(t)) then
                t = [t, t]
                v = [v, v]
                uu = [uu, uu]
            end if
            n = n + 1
            t(n) = x(1)
            v(n) = x(2)
            uu(n) = x(3)
        end do
        call traps_restore(halting)
        close (u)
        if (n < MIN_SAMPLES) then
            call set_error(stat, ERR_DECK, head//itoa(n)//' samples; allowed: at least '// &
                itoa(MIN_SAMPLES))
            return
        end if
        rec%t = t(1:n)
        rec%v = v(1:n)
        rec%has_u = ncol1 == 3
        if (rec%has_u) then
            rec%u = uu(1:n)
        else
            allocate (rec%u(n))
            rec%u = 1.0_dp
        end if
    contains
        subroutine fail(what)
            character(len=*), intent(in) :: what
            call traps_restore(halting)
            call set_error(stat, ERR_DECK, head//what)
            close (u)
        end subroutine fail
    end subroutine read_record

    !> The record file of a deck: &measurement record relative to the deck's folder
    !! (d%record_path), or as given.
    pure function record_file(d) result(path)
        type(deck_t), intent(in) :: d
        character(len=:), allocatable :: path
        path = trim(d%record)
        if (allocated(d%record_path)) path = d%record_path
    end function record_file

    !> The numbers of one line (blanks, tabs or commas between them): up to 3 in x, ncol of
    !! them (4 when there are more); msg names a token that is not a number.
    subroutine split(line, x, ncol, msg)
        character(len=*), intent(in) :: line
        real(dp), intent(out) :: x(3)
        integer, intent(out) :: ncol
        character(len=*), intent(out) :: msg
        integer :: i, j, ios
        real(dp) :: val
        x = 0.0_dp
        ncol = 0
        msg = ''
        i = 1
        do
            do while (i <= len(line))
                if (index(' ,'//achar(9)//achar(13), line(i:i)) == 0) exit
                i = i + 1
            end do
            if (i > len(line)) return
            j = i
            do while (j <= len(line))
                if (index(' ,'//achar(9)//achar(13), line(j:j)) > 0) exit
                j = j + 1
            end do
            if (verify(line(i:j - 1), '0123456789+-.eEdDnNaAiIfF') /= 0) then
                msg = '''' // line(i:min(j - 1, i + 30)) // ''' is not a number'
                return
            end if
            read (line(i:j - 1), *, iostat=ios) val
            if (ios /= 0) then
                msg = '''' // line(i:min(j - 1, i + 30)) // ''' is not a number'
                return
            end if
            ncol = min(ncol + 1, 4)
            if (ncol <= 3) x(ncol) = val
            i = j
        end do
    end subroutine split

    !> The record's mean period (s): twice the mean spacing of the crossings of its mean
    !! value, up and down (linear interpolation between samples; a crossing counts only
    !! after the signal has been beyond the mean, on the side it leaves, by a tenth of its
    !! largest excursion, so noise does not add crossings).  0 when fewer than two crossings.
    function mean_period(rec) result(tp)
        type(record_t), intent(in) :: rec
        real(dp) :: tp
        real(dp) :: mean, band, tc, t_first, t_last, a, b
        integer :: i, nc, side
        tp = 0.0_dp
        mean = sum(rec%v)/size(rec%v)
        band = 0.1_dp*maxval(abs(rec%v - mean))
        side = 0                                ! -1 below the band, +1 above, 0 not yet
        nc = 0
        t_first = 0.0_dp
        t_last = 0.0_dp
        do i = 2, size(rec%v)
            a = rec%v(i - 1) - mean
            b = rec%v(i) - mean
            if (a < -band) side = -1
            if (a > band) side = 1
            if ((side == -1 .and. a < 0.0_dp .and. b >= 0.0_dp) .or. &
                (side == 1 .and. a > 0.0_dp .and. b <= 0.0_dp)) then
                tc = rec%t(i - 1) + (rec%t(i) - rec%t(i - 1))*a/(a - b)
                nc = nc + 1
                if (nc == 1) t_first = tc
                t_last = tc
                side = 0
            end if
        end do
        if (nc >= 2) tp = 2.0_dp*(t_last - t_first)/(nc - 1)
    end function mean_period

    ! ------------------------------------------------------------------ the model

    !> The model at the record's first n sample times, for the rig d with release at t0
    !! (s): theta4 (rad) or W = omega . n3 (rad/s) when rate.  A sample before t0 sees the
    !! start.  The model runs through the run loop from &start (the deck's rtol, atol and
    !! integrator), in memory.
    subroutine record_model(d, t, t0, rate, vals, stat)
        type(deck_t), intent(in) :: d           !! the rig (I1, damping, start as fitted)
        real(dp), intent(in) :: t(:)            !! sample times (s), increasing
        real(dp), intent(in) :: t0              !! release (s)
        logical, intent(in) :: rate             !! W instead of theta4
        real(dp), intent(out) :: vals(:)        !! the model at t(1:size(vals))
        type(status_t), intent(out) :: stat     !! the start's or the run's failure
        type(pendulum_t) :: p
        type(kane_run_t) :: m
        type(record_sink_t) :: sink
        real(dp) :: y0(NSTATE), th0(5), s, v0
        real(dp), allocatable :: taus(:)
        integer :: n, i0, i
        n = size(vals)
        vals = 0.0_dp
        call make_pendulum(d, p, stat)
        if (stat%code /= 0) return
        call start_state(d, p, y0, th0, stat)
        if (stat%code /= 0) return
        s = sqrt(d%g/d%b_prime)                 ! tau per second
        sink%rate = rate
        sink%p = p
        call sample_value(sink, y0, th0(3), v0, stat)
        if (stat%code /= 0) return
        i0 = n + 1
        do i = 1, n
            if (t(i) >= t0) then
                i0 = i
                exit
            end if
            vals(i) = v0
        end do
        if (rate) vals(1:i0 - 1) = vals(1:i0 - 1)*s
        if (i0 > n) return
        allocate (taus(0:n - i0), sink%vals(0:n - i0))
        taus = (t(i0:n) - t0)*s
        if (taus(n - i0) <= 0.0_dp) then
            vals(i0:n) = v0*merge(s, 1.0_dp, rate)
            return
        end if
        call kane_run_start(m, p, y0, th0(3), d%rtol, d%atol, integrator_of(d), &
                            taus(n - i0), 'raise &integration rtol/atol', stat)
        if (stat%code /= 0) return
        call drive(m, taus, sink, stat)
        if (stat%code /= 0) return
        vals(i0:n) = sink%vals
        if (rate) vals(i0:n) = vals(i0:n)*s
    end subroutine record_model

    !> theta4 (rad) or W = omega . n3 (rad per unit tau) of a chart state.
    subroutine sample_value(sink, y, th3, v, stat)
        type(record_sink_t), intent(in) :: sink
        real(dp), intent(in) :: y(NSTATE)
        real(dp), intent(in) :: th3
        real(dp), intent(out) :: v
        type(status_t), intent(out) :: stat
        type(motion_t) :: mo
        stat%code = 0
        if (.not. sink%rate) then
            v = y(4)
            return
        end if
        call evaluate(sink%p, y, th3, mo, stat, motion_parts_t(.false., .false., .false., .false.))
        v = mo%omega(3)
    end subroutine sample_value

    !> One sample of the model (record_sink_t).
    subroutine record_take(sink, m, k, t, y, stat)
        class(record_sink_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k                !! sample (from 0)
        real(dp), intent(in) :: t               !! its tau
        real(dp), intent(in) :: y(:)            !! chart state there
        type(status_t), intent(out) :: stat
        real(dp) :: th3
        th3 = 0.0_dp
        select type (m)
        type is (kane_run_t)
            th3 = m%th3
        end select
        call sample_value(sink, y, th3, sink%vals(k), stat)
        if (stat%code /= 0) stat%msg = stat%msg//' at tau = '//sci(t)
    end subroutine record_take

    !> The deck with the parameters p of the fit set (I1, c_v, c_q, amplitude), and t0.
    subroutine apply_parameters(prob, p, d, t0)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: p(:)
        type(deck_t), intent(out) :: d
        real(dp), intent(out) :: t0
        integer :: j
        d = prob%d
        t0 = prob%t0
        do j = 1, prob%np
            select case (prob%which(j))
            case (P_I1)
                d%inertia(1) = p(j)
            case (P_CV)
                d%c_v = p(j)
            case (P_CQ)
                d%c_q = p(j)
            case (P_AMP)
                d%amplitude = p(j)
            case default
                t0 = p(j)
            end select
        end do
    end subroutine apply_parameters

    !> Residuals (model - measured)/u_i over the first nuse samples.  A parameter set the
    !! model cannot take (I1 <= 0, an amplitude outside 0 .. 180 degrees, a cable slack, ...)
    !! is a failed evaluation.
    subroutine record_residual(prob, p, r, stat)
        class(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        type(deck_t) :: d
        real(dp) :: t0
        real(dp), allocatable :: vals(:)
        call apply_parameters(prob, p, d, t0)
        r = 0.0_dp
        if (.not. (d%inertia(1) > 0.0_dp) .or. .not. (d%amplitude > 0.0_dp .and. &
            d%amplitude < 180.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'parameters out of the model''s range')
            return
        end if
        allocate (vals(prob%nuse))
        call record_model(d, prob%rec%t(1:prob%nuse), t0, prob%rate, vals, stat)
        if (stat%code /= 0) return
        r = (vals - prob%rec%v(1:prob%nuse))*prob%w(1:prob%nuse)
        if (.not. all_finite(r)) call set_error(stat, ERR_NUMERIC, 'non-finite model values')
    end subroutine record_residual

    ! ------------------------------------------------------------------ the fit

    !> The record fit of a deck: the problem (estimated parameters, start values,
    !! difference steps) from the deck and the record.
    subroutine fit_problem(d, rec, prob, p0, h)
        type(deck_t), intent(in) :: d
        type(record_t), intent(in) :: rec
        type(record_fit_t), intent(out) :: prob
        real(dp), allocatable, intent(out) :: p0(:), h(:)
        real(dp) :: tp
        integer :: j, k
        prob%d = d
        prob%rec = rec
        prob%rate = trim(d%quantity) == 'rate'
        prob%t0 = 0.0_dp
        prob%nuse = size(rec%t)
        prob%w = 1.0_dp/rec%u
        prob%np = 0
        do k = 1, 5
            if (estimated(d, PARAM_NAMES(k))) then
                prob%np = prob%np + 1
                prob%which(prob%np) = k
            end if
        end do
        allocate (p0(prob%np), h(prob%np))
        tp = mean_period(rec)
        if (.not. (tp > 0.0_dp)) tp = rec%t(size(rec%t)) - rec%t(1)
        do j = 1, prob%np
            select case (prob%which(j))
            case (P_I1)
                p0(j) = d%inertia(1)
                h(j) = H_REL*d%inertia(1)
            case (P_CV)
                p0(j) = d%c_v
                h(j) = H_REL*max(d%c_v, DAMP_REF*d%mass*d%b_prime*sqrt(d%g*d%b_prime))
            case (P_CQ)
                p0(j) = d%c_q
                h(j) = H_REL*max(d%c_q, DAMP_REF*d%mass*d%b_prime**2)
            case (P_AMP)
                p0(j) = d%amplitude
                h(j) = H_REL*max(d%amplitude, 1.0_dp)
            case default
                p0(j) = 0.0_dp
                h(j) = H_REL*tp
            end select
        end do
    end subroutine fit_problem

    !> Fit the record by Levenberg-Marquardt on growing windows (about two mean periods of
    !! the record, then twice as long each time, then the whole record), each from the
    !! last estimate.  res: the last fit (whole record); iterations summed over windows.
    subroutine fit_record(prob, p0, h, res, stat)
        type(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p0(:), h(:)
        type(lsq_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: part
        real(dp) :: tp, span, win
        real(dp), allocatable :: p(:)
        integer :: n, iters, evals
        n = size(prob%rec%t)
        tp = mean_period(prob%rec)
        span = prob%rec%t(n) - prob%rec%t(1)
        p = p0
        iters = 0
        evals = 0
        win = 2.0_dp*tp
        if (.not. (tp > 0.0_dp)) win = 2.0_dp*span
        do
            prob%nuse = n
            if (win < span) prob%nuse = max(count(prob%rec%t <= prob%rec%t(1) + win), &
                                            2*prob%np + 2)
            if (prob%nuse >= n) exit
            opts%xtol = 1.0e-6_dp
            opts%chi2_tol = 1.0_dp
            call lm_fit(prob, p, h, prob%nuse, opts, part, stat)
            iters = iters + part%iterations
            evals = evals + part%evaluations
            if (stat%code /= 0) then
                stat%msg = 'the fit on the first '//itoa(prob%nuse)//' samples: '//stat%msg
                res = part
                res%iterations = iters
                res%evaluations = evals
                return
            end if
            p = part%p
            win = 2.0_dp*win
        end do
        prob%nuse = n
        opts = lsq_options_t()
        call lm_fit(prob, p, h, n, opts, res, stat)
        res%iterations = res%iterations + iters
        res%evaluations = res%evaluations + evals
    end subroutine fit_record

    ! ------------------------------------------------------------------ the analysis

    !> Run analyses = 'identify' for a deck and write OUTDIR/NAME.identify (and, with a
    !! record, OUTDIR/NAME.fit.dat) into `files`.  The Monte Carlo is a sweep over the ranks
    !! and threads, checkpointed to OUTDIR/NAME.identify_mc.partial (options: --resume and
    !! the interval; report: how its sweep went, ranks 1 without Monte Carlo).
    subroutine run_identify(d, outdir, res, stat, files, options, report)
        type(deck_t), intent(in) :: d           !! the deck (identify_ready passed)
        character(len=*), intent(in) :: outdir  !! output directory
        type(identify_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC (exit 3), ERR_IO
        type(out_files_t), intent(inout) :: files   !! the run's files
        type(sweep_options_t), intent(in), optional :: options  !! --resume, the interval
        type(sweep_report_t), intent(out), optional :: report   !! of the Monte Carlo
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
    end subroutine run_identify

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
        n = d%n_periods
        u = input_u(d)
        associate (per => d%periods(1:n), amps => d%amplitudes(1:n))
            call invert_periods(d, per, amps, u, f, stat)
            if (stat%code /= 0) return
            if (u%period == 0.0_dp .and. n >= 2) then
                ! no stated timing uncertainty: the periods' scatter about the model is it
                ! (s^2 = sum of squares over n - 1), and the inversion is weighted with it
                res%u_period_scatter = sqrt(sum((f%model_periods - per)**2)/(n - 1))
                u%period = res%u_period_scatter
                if (u%period > 0.0_dp) call invert_periods(d, per, amps, u, f, stat)
                if (stat%code /= 0) return
            end if
            call period_budget(d, per, amps, u, f, stat)
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
        res%periods_exact = is_torsion_rig(d)
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
        res%i1_linear = linear_inertia(d, res%period_linear)
        res%linear_error = res%i1_linear/res%i1 - 1.0_dp
    end subroutine identify_periods

    !> I1 (and the other parameters asked for) from a record: the fit, the first-order
    !! budget, Monte Carlo when asked (its sweep checkpointed in outdir when given, see
    !! run_identify).
    subroutine identify_record(d, rec, res, stat, outdir, options, report, files)
        type(deck_t), intent(in) :: d
        type(record_t), intent(in) :: rec
        type(identify_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        character(len=*), intent(in), optional :: outdir
        type(sweep_options_t), intent(in), optional :: options
        type(sweep_report_t), intent(inout), optional :: report
        type(out_files_t), intent(in), optional :: files
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
            res%i1_linear = linear_inertia(d, res%period_linear)
            res%linear_error = res%i1_linear/res%i1 - 1.0_dp
        end if
    end subroutine identify_record

    !> A fit that gave no estimate (ERR_NUMERIC, exit 3): the message gets the residual
    !! and what to check.
    subroutine explain_fit_failure(stat, prob, fit)
        type(status_t), intent(inout) :: stat
        type(record_fit_t), intent(in) :: prob
        type(lsq_result_t), intent(in) :: fit
        character(len=:), allocatable :: what
        what = stat%msg
        if (index(what, 'identify: ') == 1) what = what(11:)
        stat%code = ERR_NUMERIC
        stat%msg = 'identify: '//what//' (residual rms '// &
            sci(sqrt(sum((fit%r/prob%w)**2)/max(1, size(fit%r))))// &
            trim(merge(' rad  ', ' rad/s', .not. prob%rate))//'); check the record''s'// &
            ' units (t in s, '//trim(merge('theta4 in rad', 'W in rad/s   ', &
            .not. prob%rate))//') and &measurement quantity, the start (&start '// &
            'amplitude, the release time t0), the rig''s lengths and the start '// &
            'value of I1 (&body inertia(1)), or estimate fewer parameters'
    end subroutine explain_fit_failure

    !> C = s^2 (J^T J)^-1 from the singular values of J with its columns scaled to unit norm
    !! (ERR_NUMERIC naming the parameters when J is rank deficient: the record does not
    !! determine them together).
    subroutine covariance(jac, s2, cov, stat)
        real(dp), intent(in) :: jac(:, :)
        real(dp), intent(in) :: s2
        real(dp), allocatable, intent(out) :: cov(:, :)
        type(status_t), intent(out) :: stat
        real(dp) :: cn(size(jac, 2)), js(size(jac, 1), size(jac, 2)), sv(size(jac, 2))
        real(dp) :: vt(size(jac, 2), size(jac, 2))
        integer :: n, i, j
        n = size(jac, 2)
        allocate (cov(n, n))
        cov = 0.0_dp
        do j = 1, n
            cn(j) = norm2(jac(:, j))
            if (.not. (cn(j) > 0.0_dp)) then
                call set_error(stat, ERR_NUMERIC, 'identify: the record does not depend on '// &
                    'parameter '//itoa(j)//' of &measurement estimate; estimate fewer parameters')
                return
            end if
            js(:, j) = jac(:, j)/cn(j)
        end do
        call la_svd(js, sv, vt, stat)
        if (stat%code /= 0) return
        if (sv(n) < sv(1)/COND_MAX) then
            call set_error(stat, ERR_NUMERIC, 'identify: the record does not determine the '// &
                'estimated parameters together (condition number '//sci(sv(1)/sv(n), 1)// &
                '); estimate fewer parameters or use a longer record')
            return
        end if
        do j = 1, n
            do i = 1, n
                cov(i, j) = s2*sum(vt(:, i)*vt(:, j)/sv**2)/(cn(i)*cn(j))
            end do
        end do
    end subroutine covariance

    !> dp/dx_j = -(J^T J)^-1 J^T dr/dx_j at the estimate (dr/dx by central differences with
    !! a relative step H_REL; the weights are in J and r).
    subroutine input_sensitivity(prob, p, jac, j, x, dpdx, stat)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: p(:), jac(:, :)
        integer, intent(in) :: j                !! input: 1 mass .. 6 g, 7 amplitude
        real(dp), intent(in) :: x               !! its value
        real(dp), intent(out) :: dpdx(:)
        type(status_t), intent(out) :: stat
        type(record_fit_t) :: pp, pm
        real(dp) :: hx, rp(size(jac, 1)), rm(size(jac, 1))
        hx = H_REL*abs(x)
        pp = prob
        pm = prob
        call set_input(pp%d, j, x + hx)
        call set_input(pm%d, j, x - hx)
        call pp%residual(p, rp, stat)
        if (stat%code /= 0) return
        call pm%residual(p, rm, stat)
        if (stat%code /= 0) return
        call la_lstsq(jac, (rp - rm)/(2.0_dp*hx), dpdx, stat)
        dpdx = -dpdx
    end subroutine input_sensitivity

    !> Set input j of an uncertainty budget (1 mass, 2 l, 3 l_prime, 4 b, 5 b_prime (both
    !! body attachment points move, move_b_prime), 6 g, 7 the start amplitude) to v.
    subroutine set_input(d, j, v)
        type(deck_t), intent(inout) :: d
        integer, intent(in) :: j
        real(dp), intent(in) :: v
        select case (j)
        case (1)
            d%mass = v
        case (2)
            d%l = v
        case (3)
            d%l_prime = v
        case (4)
            d%b = v
        case (5)
            call move_b_prime(d, v)
        case (6)
            d%g = v
        case default
            d%amplitude = v
        end select
    end subroutine set_input

    !> The inputs of a record fit's budget and Monte Carlo: mass, l, l_prime, b, b_prime,
    !! g, and the start amplitude when it is held (not estimated, &start mode 'raised'):
    !! their names, values and standard uncertainties (in the order of set_input).
    subroutine budget_inputs(d, xname, xval, ux)
        type(deck_t), intent(in) :: d
        character(len=16), allocatable, intent(out) :: xname(:)
        real(dp), allocatable, intent(out) :: xval(:), ux(:)
        xname = [character(len=16) :: 'mass', 'l', 'l_prime', 'b', 'b_prime', 'g']
        xval = [d%mass, d%l, d%l_prime, d%b, d%b_prime, d%g]
        ux = [d%u_mass, d%u_l, d%u_l_prime, d%u_b, d%u_b_prime, d%u_g]
        if (.not. estimated(d, 'amplitude') .and. trim(d%mode) == 'raised') then
            xname = [xname, [character(len=16) :: 'amplitude']]
            xval = [xval, d%amplitude]
            ux = [ux, d%u_amplitude]
        end if
    end subroutine budget_inputs

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

    !> The samples of a record fit's Monte Carlo from the deck, its record and the payload
    !! of record_monte_carlo (the task rank 0 runs and the other ranks build).
    subroutine record_mc_task(d, rec, payload, task)
        type(deck_t), intent(in) :: d
        type(record_t), intent(in) :: rec
        real(dp), intent(in) :: payload(:)      !! crc (2), sigma, np, phat, u_p, jac
        type(record_mc_task_t), intent(out) :: task
        real(dp), allocatable :: p0(:), h(:)
        character(len=16), allocatable :: xname(:)
        integer :: np, m
        call fit_problem(d, rec, task%prob, p0, h)
        call budget_inputs(d, xname, task%xval, task%ux)
        m = size(rec%t)
        task%sigma = payload(3)
        np = nint(payload(4))
        task%phat = payload(5:4 + np)
        task%u_p = payload(5 + np:4 + 2*np)
        task%jac = reshape(payload(5 + 2*np:4 + 2*np + m*np), [m, np])
        task%nest = np
    end subroutine record_mc_task

    !> The task of identify's Monte Carlo (sweep 'identify_mc') as the other ranks of an MPI
    !! run build it: from the deck (its periods, or its record, read here and checked
    !! against rank 0's by its CRC-64) and the sweep's payload.  ERR_DECK when the record
    !! cannot be read or is another than rank 0's.
    subroutine identify_mc_task(d, payload, task, stat)
        type(deck_t), intent(in) :: d           !! the deck
        real(dp), intent(in) :: payload(:)      !! the sweep's payload
        class(sweep_task_t), allocatable, intent(out) :: task
        type(status_t), intent(out) :: stat     !! ERR_DECK
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
    end subroutine identify_mc_task

    !> Monte Carlo sample k of a record fit: inputs and measured values drawn from stream k
    !! of the seed, then the refit from the estimate; est: the sample's parameters (I1
    !! first).  A failed refit: ERR_NUMERIC naming the sample.
    subroutine record_mc_point(self, k, est, stat)
        class(record_mc_task_t), intent(in) :: self
        integer, intent(in) :: k                !! sample number
        real(dp), intent(out) :: est(:)         !! the sample's parameters
        type(status_t), intent(out) :: stat
        type(record_fit_t) :: q
        type(rng_t) :: g
        type(lsq_result_t) :: fit
        real(dp) :: p(size(self%phat)), dp_(size(self%phat)), r(size(self%jac, 1))
        real(dp) :: h(size(self%phat))
        integer :: j, it
        logical :: done
        est = 0.0_dp
        g = rng_stream(self%prob%d%seed, k)
        q = self%prob
        do j = 1, size(self%xval)
            call set_input(q%d, j, self%xval(j) + self%ux(j)*rng_normal(g))
        end do
        do j = 1, size(q%rec%v)
            if (self%prob%rec%has_u) then
                q%rec%v(j) = self%prob%rec%v(j) + self%prob%rec%u(j)*rng_normal(g)
            else
                q%rec%v(j) = self%prob%rec%v(j) + self%sigma*rng_normal(g)
            end if
        end do
        ! Gauss-Newton with the estimate's Jacobian
        p = self%phat
        done = .false.
        do it = 1, 8
            call q%residual(p, r, stat)
            if (stat%code /= 0) exit
            call la_lstsq(self%jac, -r, dp_, stat)
            if (stat%code /= 0) exit
            p = p + dp_
            if (all(abs(dp_) <= 1.0e-3_dp*self%u_p + 1.0e-14_dp*abs(p))) then
                done = .true.
                exit
            end if
        end do
        if (.not. done) then
            do j = 1, size(p)
                h(j) = H_REL*max(abs(self%phat(j)), self%u_p(j))
            end do
            call lm_fit(q, self%phat, h, size(r), lsq_options_t(), fit, stat)
            if (stat%code /= 0) then
                stat%code = ERR_NUMERIC
                stat%msg = 'Monte Carlo sample '//itoa(k)//': '//stat%msg
                return
            end if
            p = fit%p
        end if
        stat%code = 0
        est = p
    end subroutine record_mc_point

    ! ------------------------------------------------------------------ output

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

    ! ------------------------------------------------------------------ synthetic records

    !> A record made by the program itself: the deck's rig (with its &damping) released
    !! from &start, sampled every 1/rate_hz s from 0 to duration (s), theta4 (quantity
    !! 'angle', rad) or W (quantity 'rate', rad/s) with seeded normal noise of standard
    !! deviation sigma (stream 0 of seed), written to path (t with 6 decimals, the value with
    !! 10 significant digits: the noise is far above both, and the text repeats exactly).
    subroutine make_record(d, duration, rate_hz, sigma, seed, quantity, path, stat)
        type(deck_t), intent(in) :: d           !! the true rig (simulate deck)
        real(dp), intent(in) :: duration, rate_hz, sigma   !! s, Hz, record units
        integer, intent(in) :: seed
        character(len=*), intent(in) :: quantity    !! 'angle' or 'rate'
        character(len=*), intent(in) :: path
        type(status_t), intent(out) :: stat
        type(out_files_t) :: files
        type(rng_t) :: g
        real(dp), allocatable :: t(:), v(:)
        integer :: n, i, u, ios
        character(len=64) :: line
        n = nint(duration*rate_hz)
        allocate (t(0:n), v(0:n))
        do i = 0, n
            t(i) = i/rate_hz
        end do
        call record_model(d, t, 0.0_dp, quantity == 'rate', v, stat)
        if (stat%code /= 0) return
        g = rng_stream(seed, 0)
        do i = 0, n
            v(i) = v(i) + sigma*rng_normal(g)
        end do
        call files%open(path, u, stat)
        if (stat%code /= 0) return
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar make_record: '//trim(d%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# simulated from '//d%path// &
            ' (&damping c_v = '//sci(d%c_v, 6)//', c_q = '//sci(d%c_q, 6)//', I1 = '// &
            sci(d%inertia(1), 6)//'), noise sigma = '//sci(sigma, 3)//', seed '//itoa(seed)
        if (ios == 0) write (u, '(a)', iostat=ios) '# t (s from release)  '// &
            trim(merge('theta4 (rad)', 'W (rad/s)   ', quantity == 'angle'))
        do i = 0, n
            write (line, '(f12.6,es19.9e3)') t(i), v(i)
            if (ios == 0) write (u, '(a)', iostat=ios) trim(line)
        end do
        call files%close(u, ios, stat)
        if (stat%code == 0) call files%commit(stat)
        if (stat%code /= 0) call files%discard()
    end subroutine make_record


end module identify
