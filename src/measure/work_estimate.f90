!> Work before it is done: what a measurement deck asks the model to do, weighed before any
!! computing (the rule: a deck ends within 10 s, or is refused at once with the
!! likely mistake named, or says within 10 s, on one line, what it is doing and how long it
!! will take).  Used by identify_ready for each release.
!!
!! * The rig's reference period, T_attach = 2 pi (l b'/(g b))^(1/2): the classical period
!!   of torsion with the body's mass at its two cable attachments, I1 = m (b'/2)^2 (l the
!!   mean cable length).  T/T_attach is the body's radius of gyration about the vertical
!!   over b'/2.  The deck's guess: the classical period at &body inertia(1), when given.
!! * Refused as no rig gives them (ERR_MODEL, exit 4): a timed period (per cycle), or the
!!   period a record swings with, more than GYRATION_MAX times T_attach (a radius of
!!   gyration more than 50 b'; a long rod on closely spaced cables reaches 20); with one
!!   release, &body inertia given and amplitudes up to 90 degrees, a classical I1 (from the
!!   mean period at the smallest amplitude) that the checks after the model
!!   (check_physical: 10 % beyond the triangle inequality, 50 % from the classical value)
!!   refuse whatever the model gives: above 2.2 (I2 + I3), a long period whose simulation
!!   would be long work (a short one is cheap, and the inversion says which periods no
!!   positive I1 gives).  The likely causes are named (CAUSES_HIGH, CAUSES_UNITS).
!! * A record (ERR_DECK, exit 2): sampled more coarsely than half the period of its swing
!!   (the deck's guess, else the record's own; times that are whole numbers a unit apart
!!   are named as frame numbers); a gap between two samples longer than GAP_PERIODS_MAX
!!   periods (the fit cannot follow the swing's phase across it); with t0 not estimated, a
!!   first sample more than START_PERIODS_MAX periods after t = 0 (a clock that does not
!!   count from the release: the model starts there); values 57 times those of the start
!!   (degrees read as radians) or, with their unit stated (record_units or the column's
!!   name) and t0 not estimated, 1/57 of them (radians said to be degrees); after the fit,
!!   a fitted release amplitude 57 times or 1/57 of &start amplitude, t0 estimated or not
!!   (check_fitted_amplitude).
!! * The work: the model runs the analysis will make, counted from the deck (the
!!   inversion, the budget, the Monte Carlo over the threads, the figure's curves:
!!   periods_runs, record_runs); identify times one run now (a probe: one model period, or
!!   the model over the record's first periods, scaled to its whole span), and work_note
!!   says the product on one line when it exceeds note_after() seconds (5; module
!!   progress).
!! The record's own period is the median spacing of its crossings of its median value
!! (robust to a gap, unlike a mean), times two.  No module state; no routine stops.
module work_estimate
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_MODEL
    use text, only: itoa, itoa_text, sci, fixed
    use rig_groups, only: body_group_t, start_group_t, integration_group_t
    use measure_groups, only: measurement_group_t
    use rig, only: rig_t, accuracy_t, accuracy_of
    use records, only: record_t
    use inputs, only: input_t, no_effect_on_torsion
    use progress, only: note_after, say_note, duration
    use omp_lib, only: omp_get_max_threads
    implicit none
    private

    public :: reference_periods, check_timings, check_record_times, record_swing_period, &
              median_of, periods_runs, record_runs, work_note, check_fitted_amplitude

    !> Largest period over T_attach (the radius of gyration over b'/2) taken for a rig.
    real(dp), parameter, public :: GYRATION_MAX = 100.0_dp
    !> A radius of gyration sqrt(I1/m) more than this many times b_prime (the spacing of
    !! the body's own attachment points) is not a body hung by them.
    real(dp), parameter, public :: RADIUS_SPACING_MAX = 30.0_dp
    !> Longest gap in a record, in periods of its swing.
    real(dp), parameter, public :: GAP_PERIODS_MAX = 10.0_dp
    !> Latest first sample of a record whose times count from the release (t0 not
    !! estimated), in periods of its swing.
    real(dp), parameter, public :: START_PERIODS_MAX = 2.0_dp
    !> Degrees in a radian: a record's values this many times (or 1/this) what the release
    !! gives are in the other unit; a factor within DEG_FACTOR_BAND of it counts.
    real(dp), parameter :: DEG_RATIO = 57.29577951308232_dp, DEG_FACTOR_BAND = 3.0_dp
    !> The margins of identify's checks after the model (check_physical).
    real(dp), parameter, public :: TRIANGLE_MARGIN = 1.1_dp, LINEAR_GAP_MAX = 0.5_dp
    !> What makes an I1 too large, too small, a period too long (for messages).
    character(len=*), parameter, public :: CAUSES_HIGH = 'likely: periods typed as the '// &
        'totals of several cycles (give &measurement cycles = N), periods or lengths in '// &
        'other units than the deck''s, b or b_prime typed as twice the spacing, or I2, I3 '// &
        'too rough'
    character(len=*), parameter, public :: CAUSES_LOW = 'likely: b or b_prime typed as '// &
        'half the spacing (they are the full distances between the two cables), half '// &
        'periods typed as periods, periods or lengths in other units than the deck''s, or '// &
        'I2, I3 too rough'
    character(len=*), parameter, public :: CAUSES_UNITS = 'likely: times in other units '// &
        'than s (ms), the totals of many cycles (give &measurement cycles = N), or lengths '// &
        'in other units than the deck''s'

    !> Model iterations assumed per fit or inversion, per refit from the estimate.
    integer, parameter :: ITER_FIT = 8, ITER_REFIT = 4

contains

    !> The rig's reference periods (s): t_attach (the classical period with the body's mass
    !! at its cable attachments) and t_guess (the classical period at &body inertia(1); -1
    !! when the deck gives no inertia).
    subroutine reference_periods(bod, rg, t_attach, t_guess)
        type(body_group_t), intent(in) :: bod   !! the deck's &body (inertia given?)
        type(rig_t), intent(in) :: rg           !! the rig
        real(dp), intent(out) :: t_attach, t_guess
        real(dp) :: lbar
        lbar = 0.5_dp*(rg%l + rg%l_prime)
        t_attach = 2.0_dp*pi*sqrt(lbar*rg%b_prime/(rg%g*rg%b))
        t_guess = -1.0_dp
        if (bod%gave('inertia') .and. rg%inertia(1) > 0.0_dp) &
            t_guess = 4.0_dp*pi*sqrt(rg%inertia(1)*lbar/(rg%mass*rg%g*rg%b*rg%b_prime))
    end subroutine reference_periods

    !> The timed periods of a release (per cycle, s, at amplitudes amps in degrees) against
    !! what a rig can give (see the module header): ERR_MODEL naming the likely mistake.
    !! single: the deck's one release (the triangle check on the classical I1 applies).
    subroutine check_timings(bod, rg, per, amps, single, stat)
        type(body_group_t), intent(in) :: bod   !! the deck's &body
        type(rig_t), intent(in) :: rg
        real(dp), intent(in) :: per(:), amps(:)
        logical, intent(in) :: single
        type(status_t), intent(out) :: stat
        real(dp) :: ta, tg, ratio, amin, tlin, i1lin, s23
        integer :: i
        logical, allocatable :: sel(:)
        stat%code = STATUS_OK
        call reference_periods(bod, rg, ta, tg)
        do i = 1, size(per)
            ratio = per(i)/ta
            if (ratio > GYRATION_MAX) then
                call set_error(stat, ERR_MODEL, 'identify: periods('//itoa(i)//') = '// &
                    sci(per(i), 4)//' s (per cycle) is '//itoa(nint(ratio))//' times the '// &
                    'period of this rig with the body''s mass at its cable attachments '// &
                    '(2 pi (l b_prime/(g b))^(1/2) = '//sci(ta, 4)//' s): a radius of '// &
                    'gyration of '//itoa(nint(ratio/2))//' b_prime, beyond '// &
                    itoa(nint(GYRATION_MAX/2))//' b_prime no bifilar body has; '//CAUSES_UNITS)
                return
            end if
        end do
        ! what the rig itself allows, with or without &body inertia: at amplitudes up to 90
        ! degrees (the classical I1 at most 20 % above the model's), a classical I1 above
        ! m (l^2 + b^2), or a radius of gyration sqrt(I1/m) beyond RADIUS_SPACING_MAX b_prime
        do i = 1, size(per)
            if (amps(i) > 90.0_dp) cycle
            i1lin = rg%mass*rg%g*rg%b*rg%b_prime*per(i)**2/(16.0_dp*pi**2*(0.5_dp* &
                    (rg%l + rg%l_prime)))
            s23 = rg%mass*(max(rg%l, rg%l_prime)**2 + max(rg%b, rg%b_prime)**2)
            ratio = sqrt(i1lin/rg%mass)/rg%b_prime
            if ((1.0_dp - 0.2_dp)*i1lin > s23 .or. ratio > RADIUS_SPACING_MAX) then
                call set_error(stat, ERR_MODEL, 'identify: periods('//itoa(i)//') = '// &
                    sci(per(i), 4)//' s (per cycle) gives by the classical formula I1 = '// &
                    sci(i1lin, 4)//', a radius of gyration sqrt(I1/m) = '// &
                    sci(sqrt(i1lin/rg%mass), 3)//', '//fixed(ratio, 1)//' times b_prime; '// &
                    'allowed: I1 at most m (l^2 + b^2) = '//sci(s23, 4)//' (the longer '// &
                    'cable, the wider spacing) and a radius of gyration at most '// &
                    itoa(nint(RADIUS_SPACING_MAX))//' b_prime; likely: the total of several '// &
                    'cycles typed as one period (give &measurement cycles = N), times in '// &
                    'other units than s, or lengths in other units than the deck''s')
                return
            end if
        end do
        if (.not. single .or. .not. bod%gave('inertia') .or. maxval(amps) > 90.0_dp) return
        ! the classical I1 as combine computes it: the mean period at the smallest amplitude
        amin = minval(amps)
        sel = amps <= amin*(1.0_dp + 1.0e-9_dp)
        tlin = sum(per, sel)/count(sel)
        ! the classical formula (period_inversion's linear_inertia)
        i1lin = rg%mass*rg%g*rg%b*rg%b_prime*tlin**2/(16.0_dp*pi**2*(0.5_dp*(rg%l + rg%l_prime)))
        s23 = rg%inertia(2) + rg%inertia(3)
        if (i1lin*(1.0_dp - LINEAR_GAP_MAX) > TRIANGLE_MARGIN*s23) then
            call set_error(stat, ERR_MODEL, 'identify: the classical formula gives I1 = '// &
                sci(i1lin, 4)//' (period '//sci(tlin, 5)//' s), '// &
                fixed(i1lin/s23, 2)//' times I2 + I3 = '//sci(s23, 4)//' (&body inertia), '// &
                'and up to 90 deg the model is within 50 % of it: no rigid body has '// &
                'I1 > I2 + I3; '//CAUSES_HIGH)
        end if
    end subroutine check_timings

    !> A record's times against the rig (see the module header): ERR_MODEL for a swing no
    !! rig gives (times in ms), ERR_DECK for sampling too coarse, a gap too long, or values
    !! in degrees read as radians.  name: how the record is named in messages.
    subroutine check_record_times(bod, mea, sta, rg, rec, name, stat)
        type(body_group_t), intent(in) :: bod           !! the deck's (inertia given?)
        type(measurement_group_t), intent(in) :: mea    !! (record_units)
        type(start_group_t), intent(in) :: sta          !! (the release), normalised
        type(rig_t), intent(in) :: rg
        type(record_t), intent(in) :: rec
        character(len=*), intent(in) :: name
        type(status_t), intent(out) :: stat
        real(dp) :: ta, tg, tr, tx, dtm, gap, peak, expect, a
        integer :: n, ig
        stat%code = STATUS_OK
        n = size(rec%t)
        if (n < 3) return
        call reference_periods(bod, rg, ta, tg)
        tr = record_swing_period(rec)
        if (tr > GYRATION_MAX*ta) then
            call set_error(stat, ERR_MODEL, name//': it swings with a period of '// &
                sci(tr, 4)//' s, '//itoa(nint(tr/ta))//' times that of this rig with the '// &
                'body''s mass at its cable attachments (2 pi (l b_prime/(g b))^(1/2) = '// &
                sci(ta, 4)//' s): a radius of gyration of '//itoa(nint(tr/ta/2))// &
                ' b_prime, beyond '//itoa(nint(GYRATION_MAX/2))//' b_prime no bifilar body '// &
                'has; '//CAUSES_UNITS)
            return
        end if
        ! the swing's period: the deck's guess, else the record's own
        tx = tg
        if (.not. (tx > 0.0_dp)) tx = tr
        dtm = median_of(rec%t(2:n) - rec%t(1:n - 1))
        if (tx > 0.0_dp .and. dtm > 0.5_dp*tx) then
            call set_error(stat, ERR_DECK, name//': sampled every '//sci(dtm, 3)//' s '// &
                '(median), while the rig swings in about '//sci(tx, 3)//' s: fewer than '// &
                'two samples a period cannot show the swing; '//frames_cause()// &
                '; allowed: at least two samples a period (ten or more for a fit)')
            return
        end if
        if (.not. (tx > 0.0_dp)) tx = ta
        ig = maxloc(rec%t(2:n) - rec%t(1:n - 1), 1)
        gap = rec%t(ig + 1) - rec%t(ig)
        if (gap > GAP_PERIODS_MAX*tx .and. gap > 10.0_dp*dtm) then
            call set_error(stat, ERR_DECK, name//': a gap of '//sci(gap, 3)//' s between '// &
                'the samples at t = '//sci(rec%t(ig), 6)//' and '//sci(rec%t(ig + 1), 6)// &
                ' s, '//itoa(nint(gap/tx))//' periods of the swing (about '//sci(tx, 3)// &
                ' s): no fit follows the swing''s phase across it; allowed: gaps of at '// &
                'most '//itoa(nint(GAP_PERIODS_MAX))//' periods (a record cut in two is two '// &
                'releases of a table, each with t0 estimated)')
            return
        end if
        ! a clock that does not count from the release, with t0 not estimated: the model
        ! starts at the release, t = 0, and no fit follows the phase to the first sample
        if (.not. mea%estimated('t0') .and. tx > 0.0_dp .and. &
            rec%t(1) > START_PERIODS_MAX*tx) then
            call set_error(stat, ERR_DECK, name//': its first sample is at t = '// &
                sci(rec%t(1), 4)//' s, '//ratio_text(rec%t(1), tx)//' periods of the swing '// &
                '(about '//sci(tx, 3)//' s) after t = 0, and t0 is not estimated: the '// &
                'model starts at the release, t = 0, and no fit follows the swing''s phase '// &
                'that far; likely: a clock that does not count from the release (a '// &
                'logger''s own time, seconds since 1970); allowed: times from the release '// &
                '(the first sample within '//itoa(nint(START_PERIODS_MAX))//' periods of '// &
                't = 0), or t0 in &measurement estimate (the release found in the record)')
            return
        end if
        ! degrees read as radians: values 57 times what the start gives (a tracked point's
        ! coordinates are lengths)
        if (trim(sta%mode) /= 'raised' .or. trim(mea%quantity) == 'point') return
        ! (the start's amplitude, also when it is a start value of the fit)
        a = sta%amplitude*deg
        if (.not. (a > 0.0_dp)) return
        expect = a
        if (rec%rate) then
            if (.not. (tx > 0.0_dp)) return
            expect = a*2.0_dp*pi/tx
        end if
        peak = maxval(abs(rec%v - median_of(rec%v)))
        ! radians said to be degrees (record_units or the column's name): 1/57 of it, when
        ! the record holds the release (t0 not estimated: no decay before the record)
        if (rec%units_stated .and. rec%to_rad /= 1.0_dp .and. .not. mea%estimated('t0') .and. &
            peak < expect/20.0_dp .and. peak*DEG_RATIO > expect/DEG_FACTOR_BAND) then
            call set_error(stat, ERR_DECK, name//': its values reach '//sci(peak/deg, 3)//' '// &
                trim(rec%units)//', 1/'//itoa(nint(expect/peak))//' of what a release at '// &
                fixed(sta%amplitude, 1)//' deg gives on this rig (about '//sci(expect/deg, 3)// &
                ' '//trim(rec%units)//'): they look like '//trim(merge('rad/s', 'rad  ', &
                rec%rate))//' read as '//trim(rec%units)//' ('//trim(units_source())// &
                '); allowed: record_units = '''//trim(merge('rad/s', 'rad  ', rec%rate))// &
                ''' for a record in radians (or its column named so)')
            return
        end if
        if (rec%units_stated .and. rec%to_rad /= 1.0_dp) return
        if (rec%units_stated .and. peak > 20.0_dp*expect .and. peak/DEG_RATIO < &
            DEG_FACTOR_BAND*expect) then
            call set_error(stat, ERR_DECK, name//': its values reach '//sci(peak, 3)//' '// &
                trim(rec%units)//', '//itoa(nint(peak/expect))//' times what a release at '// &
                fixed(sta%amplitude, 1)//' deg gives on this rig (about '//sci(expect, 3)// &
                ' '//trim(rec%units)//'): they look like '//trim(merge('deg/s', 'deg  ', &
                rec%rate))//' read as '//trim(rec%units)//' ('//trim(units_source())// &
                '); allowed: record_units = '''//trim(merge('deg/s', 'deg  ', rec%rate))// &
                ''' for a record in degrees (or its column named so)')
            return
        end if
        if (rec%units_stated) return
        if (peak > 20.0_dp*expect .and. peak/57.29577951308232_dp < 3.0_dp*expect) then
            call set_error(stat, ERR_DECK, name//': its values reach '//sci(peak, 3)//' '// &
                trim(merge('rad/s', 'rad  ', rec%rate))//', '//itoa(nint(peak/expect))// &
                ' times what a release at '//fixed(sta%amplitude, 1)//' deg gives on this '// &
                'rig (about '//sci(expect, 3)//' '//trim(merge('rad/s', 'rad  ', rec%rate))// &
                '): they look like '//trim(merge('deg/s', 'deg  ', rec%rate))//'; allowed: '// &
                'record_units = '''//trim(merge('deg/s', 'deg  ', rec%rate))//''' for a '// &
                'record in degrees (or rad, rad/s)')
        end if
    contains
        !> CAUSES_UNITS, frame numbers first when the times are whole numbers a unit apart.
        function frames_cause() result(c)
            character(len=:), allocatable :: c
            c = CAUSES_UNITS
            if (abs(dtm - 1.0_dp) < 1.0e-9_dp .and. all(rec%t == anint(rec%t))) c = &
                'likely: frame numbers (give &measurement record_frame_rate = F, the '// &
                'frames a second), '//CAUSES_UNITS(len('likely: ') + 1:)
        end function frames_cause
        !> Where the record's unit was stated.
        function units_source() result(c)
            character(len=:), allocatable :: c
            c = 'record_units = '''//trim(mea%record_units)//''''
            if (len_trim(mea%record_units) == 0) c = 'its column''s name says so'
        end function units_source
    end subroutine check_record_times

    !> After a record's fit (t0 estimated or not: the fitted amplitude is the release's,
    !! the decay before the record modelled), its fitted release amplitude (degrees) against
    !! &start amplitude: about 57 times it, or 1/57 of it (within DEG_FACTOR_BAND), is a
    !! unit mistake of the record (ERR_DECK naming record_units): the fit has taken radians
    !! for degrees or degrees for radians.
    subroutine check_fitted_amplitude(mea, sta, rec, a_fit, name, stat)
        type(measurement_group_t), intent(in) :: mea    !! (estimate, record_units)
        type(start_group_t), intent(in) :: sta          !! (the release), normalised
        type(record_t), intent(in) :: rec
        real(dp), intent(in) :: a_fit                   !! the fitted amplitude (degrees)
        character(len=*), intent(in) :: name
        type(status_t), intent(out) :: stat
        real(dp) :: ratio
        stat%code = STATUS_OK
        if (.not. mea%estimated('amplitude') .or. trim(sta%mode) /= 'raised') return
        if (.not. (sta%amplitude > 0.0_dp .and. abs(a_fit) > 0.0_dp)) return
        ratio = abs(a_fit)/sta%amplitude
        if ((ratio > DEG_RATIO/DEG_FACTOR_BAND .and. ratio < DEG_RATIO*DEG_FACTOR_BAND) .or. &
            (ratio < DEG_FACTOR_BAND/DEG_RATIO .and. ratio > 1.0_dp/(DEG_FACTOR_BAND*DEG_RATIO))) &
            then
            call set_error(stat, ERR_DECK, name//': the fit releases the body from '// &
                sci(abs(a_fit), 3)//' deg, where &start amplitude = '//fixed(sta%amplitude, 1)// &
                ' deg: a factor of '//trim(merge('57  ', '1/57', ratio > 1.0_dp))//', a '// &
                'record in '//trim(merge('deg', 'rad', ratio > 1.0_dp))// &
                trim(merge('/s', '  ', rec%rate))//' read as '// &
                trim(rec%units)//'; allowed: record_units (or the value column''s name) '// &
                'saying the record''s unit: '''//trim(merge('deg  ', 'rad  ', ratio > 1.0_dp))// &
                trim(merge('/s', '  ', rec%rate))//'''')
        end if
    end subroutine check_fitted_amplitude

    !> a/b (both > 0) as a whole number for a message ('more than 1e9' beyond).
    pure function ratio_text(a, b) result(s)
        real(dp), intent(in) :: a, b
        character(len=:), allocatable :: s
        if (a < 1.0e9_dp*b) then
            s = itoa(nint(a/b))
        else
            s = 'more than 1e9'
        end if
    end function ratio_text

    !> The period a record swings with (s): twice the median spacing of its crossings of its
    !! median value, each counted after the record has been beyond a tenth of its largest
    !! excursion on the side it leaves (noise adds none); 0 with fewer than three crossings.
    function record_swing_period(rec) result(tp)
        type(record_t), intent(in) :: rec
        real(dp) :: tp
        real(dp) :: mid, band, a, b
        real(dp), allocatable :: tc(:)
        integer :: i, nc, side
        tp = 0.0_dp
        if (size(rec%v) < 3) return
        mid = median_of(rec%v)
        band = 0.1_dp*maxval(abs(rec%v - mid))
        if (.not. (band > 0.0_dp)) return
        allocate (tc(size(rec%v)))
        nc = 0
        side = 0
        do i = 2, size(rec%v)
            a = rec%v(i - 1) - mid
            b = rec%v(i) - mid
            if (a < -band) side = -1
            if (a > band) side = 1
            if ((side == -1 .and. a < 0.0_dp .and. b >= 0.0_dp) .or. &
                (side == 1 .and. a > 0.0_dp .and. b <= 0.0_dp)) then
                nc = nc + 1
                tc(nc) = rec%t(i - 1) + (rec%t(i) - rec%t(i - 1))*a/(a - b)
                side = 0
            end if
        end do
        if (nc < 3) return
        tp = 2.0_dp*median_of(tc(2:nc) - tc(1:nc - 1))
    end function record_swing_period

    !> The median of x (a copy partly sorted by Hoare's selection, expected O(n)).
    pure function median_of(x) result(m)
        real(dp), intent(in) :: x(:)
        real(dp) :: m
        real(dp), allocatable :: s(:)
        integer :: n
        n = size(x)
        m = 0.0_dp
        if (n == 0) return
        s = x
        call select_kth(s, (n + 1)/2, m)
        if (mod(n, 2) == 0) m = 0.5_dp*(m + minval(s((n + 1)/2 + 1:n)))
    end function median_of

    !> v: the k-th smallest of s (s reordered: s(1:k-1) <= s(k) <= s(k+1:)).
    pure subroutine select_kth(s, k, v)
        real(dp), intent(inout) :: s(:)
        integer, intent(in) :: k
        real(dp), intent(out) :: v
        real(dp) :: pivot, t
        integer :: lo, hi, i, j
        lo = 1
        hi = size(s)
        do while (lo < hi)
            pivot = s((lo + hi)/2)
            i = lo
            j = hi
            do while (i <= j)
                do while (s(i) < pivot)
                    i = i + 1
                end do
                do while (pivot < s(j))
                    j = j - 1
                end do
                if (i <= j) then
                    t = s(i)
                    s(i) = s(j)
                    s(j) = t
                    i = i + 1
                    j = j - 1
                end if
            end do
            if (k <= j) then
                hi = j
            else if (k >= i) then
                lo = i
            else
                exit
            end if
        end do
        v = s(k)
    end subroutine select_kth

    !> The model periods a release of n timed periods asks for (nup of them with a u, the
    !! amplitudes with u_amplitude), on a symmetric rig (sym: pure torsion) or another
    !! (simulated): the inversion, the budget (two whole inversions for each input with a
    !! u, two model periods for each period's slope and four for each amplitude's:
    !! period_budget, on every rig), the Monte Carlo over the
    !! threads, the figure's curve.  what: the work in words, for one period of `one` seconds.
    subroutine periods_runs(x, mea, n, nup, sym, one, runs, what)
        type(input_t), intent(in) :: x(:)       !! the budget's inputs (deck_inputs, .false.)
        type(measurement_group_t), intent(in) :: mea
        integer, intent(in) :: n, nup
        logical, intent(in) :: sym
        real(dp), intent(in) :: one             !! wall seconds of one model period
        real(dp), intent(out) :: runs
        character(len=:), allocatable, intent(out) :: what
        real(dp) :: inv, refit
        integer :: nu
        nu = inputs_with_u(x, sym)
        inv = real(ITER_FIT*2*n + 2*n, dp)
        refit = real(ITER_REFIT*2*n, dp)
        runs = inv + nu*2*refit + n + 41
        ! the budget's rows of the periods and amplitudes are linear (period_budget): the
        ! slope dT/dI1 of each period, and dT/dA of each when u_amplitude > 0
        runs = runs + merge(2*n, 0, nup > 0 .or. mea%u_amplitude > 0.0_dp) + &
            merge(4*n, 0, mea%u_amplitude > 0.0_dp)
        runs = runs + real(mea%monte_carlo, dp)*inv/max(1, omp_get_max_threads())
        what = itoa(n)//' period'//trim(merge('s', ' ', n > 1))//' of '// &
            trim(merge('pure torsion        ', 'the full model      ', sym))//' (about '// &
            sci(one, 1)//' s each), about '//sci(runs, 1)//' times (the inversion, the '// &
            'budget'//mc_words(mea%monte_carlo)//', the figure)'
    end subroutine periods_runs

    !> The model runs over a whole record a fit of np parameters asks for: the fit on
    !! growing windows, Huber's refits, the Jacobian and the inputs' sensitivities, the
    !! Monte Carlo's refits over the threads.  With differences of whole runs (&integration
    !! sensitivities = 'differences') an evaluation of the fit is np + 1 runs and the
    !! windows about twice the whole record's; with forward sensitivities one run carrying
    !! np columns (each about 0.4 of a plain run's work), the budget's columns ride on the
    !! fit's last run, and a Monte Carlo refit takes about two plain runs.  what: the work in
    !! words, for a run of `one` seconds over `span` s of `periods` periods.
    subroutine record_runs(x, mea, integ, np, span, periods, one, runs, what)
        type(input_t), intent(in) :: x(:)       !! the budget's inputs (deck_inputs, .true.)
        type(measurement_group_t), intent(in) :: mea
        type(integration_group_t), intent(in) :: integ   !! (sensitivities), normalised
        integer, intent(in) :: np
        real(dp), intent(in) :: span, periods, one
        real(dp), intent(out) :: runs
        character(len=:), allocatable, intent(out) :: what
        real(dp), parameter :: COLUMN = 0.4_dp
        integer :: nu
        nu = inputs_with_u(x, .false.)
        if (trim(integ%sensitivities) == 'differences') then
            runs = 2.0_dp*ITER_FIT*(np + 1) + 2*np + 2*nu
            if (trim(mea%loss) == 'huber') runs = runs + 3.0_dp*ITER_FIT*(np + 1)
            runs = runs + real(mea%monte_carlo, dp)*2*ITER_REFIT/max(1, omp_get_max_threads())
        else
            runs = ITER_FIT*(1.0_dp + COLUMN*np) + COLUMN*nu
            if (trim(mea%loss) == 'huber') runs = runs + 3.0_dp*2.0_dp*(1.0_dp + COLUMN*np)
            runs = runs + real(mea%monte_carlo, dp)*2.0_dp/max(1, omp_get_max_threads())
        end if
        what = 'the model over the record''s '//sci(span, 3)//' s (about '// &
            itoa(nint(min(periods, 1.0e9_dp)))//' periods; '//sci(one, 1)//' s a run), '// &
            'about '//sci(runs, 1)//' times (the fit of '//itoa(np)//' parameter'// &
            trim(merge('s', ' ', np > 1))//', the budget'//mc_words(mea%monte_carlo)//')'
    end subroutine record_runs

    !> The inputs of a budget with a u (on a symmetric rig, of those that enter torsion).
    pure integer function inputs_with_u(x, sym) result(n)
        type(input_t), intent(in) :: x(:)
        logical, intent(in) :: sym
        integer :: k
        n = 0
        do k = 1, size(x)
            if (x(k)%u > 0.0_dp .and. .not. (sym .and. no_effect_on_torsion(x(k)%name))) &
                n = n + 1
        end do
    end function inputs_with_u

    !> ', a Monte Carlo of N samples' (nothing for N = 0).
    pure function mc_words(n) result(s)
        integer, intent(in) :: n
        character(len=merge(27 + len_trim(itoa_text(n)), 0, n > 0)) :: s
        if (n > 0) s = ', a Monte Carlo of '//itoa(n)//' samples'
    end function mc_words

    !> One line on standard error when the work estimated exceeds note_after() seconds:
    !! 'bifilar: note: DECK: identify: about 2 min (estimated): WHAT'.
    subroutine work_note(deck_path, seconds, what)
        character(len=*), intent(in) :: deck_path   !! the deck as given
        real(dp), intent(in) :: seconds
        character(len=*), intent(in) :: what
        if (.not. (seconds > note_after())) return
        call say_note(deck_path, 'identify: about '//duration(seconds)//' of work (estimated '// &
                      'now): '//what)
    end subroutine work_note

end module work_estimate
