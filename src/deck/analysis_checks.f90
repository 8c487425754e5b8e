!> The checks of the scene's and the single analyses' groups (submodule of
!! analysis_groups): each value finite and in its range, words known, the first problem an
!! ERR_DECK status naming the group, the variable, its value, what is wrong and what is
!! allowed.  A check never changes a value (the words it compares in lower case, the
!! design's amplitude of measurement, are made here as normalise makes them).  Each
!! returns at once when an earlier check failed.
submodule (analysis_groups) analysis_checks
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: sci, commas, clip, count_words
    use value_checks, only: bad, finite, positive, over_b_prime, check_word, RATIO_MIN, &
        RATIO_MAX, RTOL_MIN
    implicit none

    real(dp), parameter :: PI_HALF = 1.5707963267948966_dp

contains

    !> &scene: model a known word, analyses known words (at least one; tabs taken as
    !! blanks).
    module procedure check_scene
        character(len=len(self%analyses)) :: analyses
        integer :: k
        if (stat%code /= STATUS_OK) return
        analyses = self%analyses
        do k = 1, len(analyses)
            if (analyses(k:k) == achar(9)) analyses(k:k) = ' '
        end do
        analyses = adjustl(analyses)
        call check_word(stat, 'scene', 'model', self%model, MODELS_ALLOWED)
        if (stat%code /= STATUS_OK) return
        call check_analyses(stat, analyses)
    end procedure check_scene

    !> &output: the columns, blank-separated names of OUTPUT_COLUMNS, or of a platform's
    !! columns (platform_columns; left as OUTPUT_COLUMNS: all of them) (check_columns).
    module procedure check_output
        if (stat%code /= STATUS_OK) return
        if (sus%cables > 2) then
            if (trim(self%columns) == OUTPUT_COLUMNS) return
            call check_columns(stat, self%columns, platform_columns(sus%cables), &
                               ' (a platform of '//itoa(sus%cables)//' cables)')
        else
            call check_columns(stat, self%columns, OUTPUT_COLUMNS, '')
        end if
    end procedure check_output

    !> &floquet: 0 < amplitude < 180 degrees, 1..MAX_SEGMENTS segments, rtol in range.
    module procedure check_floquet
        if (stat%code /= STATUS_OK) return
        call finite(stat, 'floquet', 'amplitude', self%amplitude)
        call finite(stat, 'floquet', 'rtol', self%rtol)
        if (stat%code /= STATUS_OK) return
        if (self%amplitude < FLOQUET_AMPLITUDE_MIN .or. self%amplitude >= 180.0_dp) then
            call bad(stat, 'floquet', 'amplitude', rshort(self%amplitude), &
                     'out of range', rshort(FLOQUET_AMPLITUDE_MIN)//' <= amplitude < 180 '// &
                     '(degrees of theta4)')
            return
        end if
        if (self%segments < 1 .or. self%segments > MAX_SEGMENTS) then
            call bad(stat, 'floquet', 'segments', itoa(self%segments), &
                     'number of shooting segments out of range', '1 <= segments <= '// &
                     itoa(MAX_SEGMENTS))
            return
        end if
        if (self%rtol < RTOL_MIN .or. self%rtol >= FLOQUET_RTOL_MAX) then
            call bad(stat, 'floquet', 'rtol', rshort(self%rtol), &
                     'relative tolerance out of range', '1e-14 <= rtol < 1e-2')
        end if
    end procedure check_floquet

    !> &chart: two different variables (known words), each axis a
    !! finite range inside its variable's range with 2..MAX_CHART_N points, nx*ny bounded.
    module procedure check_chart
        character(len=len(self%x)) :: x, y
        character(len=:), allocatable :: vars
        if (stat%code /= STATUS_OK) return
        vars = CHART_VARIABLES
        if (sus%cables > 2) vars = PLATFORM_CHART_VARIABLES
        call check_word(stat, 'chart', 'x', self%x, vars)
        call check_word(stat, 'chart', 'y', self%y, vars)
        if (stat%code /= STATUS_OK) then
            if (sus%cables > 2) stat%msg = stat%msg//' (a platform of '//itoa(sus%cables)// &
                ' cables)'
            return
        end if
        x = lower(adjustl(self%x))
        y = lower(adjustl(self%y))
        if (trim(x) == trim(y)) then
            call bad(stat, 'chart', 'y', quoted(y), 'the same variable as x', &
                     'y different from x, both from: '//commas(vars))
            return
        end if
        if (sus%cables > 2 .and. sus%pointwise() .and. (any([character(len=8) :: 'l', &
            'radius'] == x) .or. any([character(len=8) :: 'l', 'radius'] == y))) then
            call bad(stat, 'chart', trim(merge('x', 'y', x == 'l' .or. x == 'radius')), &
                     quoted(merge(x, y, x == 'l' .or. x == 'radius')), 'a regular '// &
                     'polygon''s variable on a platform given point by point', &
                     'amplitude, cg_offset, cg_depth, inertia_ratio (l and radius with the '// &
                     'platform given by radius, radius_prime, l)')
            return
        end if
        call chart_axis('x', x, self%x_min, self%x_max, self%nx)
        call chart_axis('y', y, self%y_min, self%y_max, self%ny)
        if (stat%code /= STATUS_OK) return
        if (self%nx*self%ny > MAX_CHART_POINTS) then
            call bad(stat, 'chart', 'ny', itoa(self%ny), 'too many chart points ' // &
                     '(nx*ny = '//itoa(self%nx*self%ny)//', nx = '//itoa(self%nx)// &
                     ')', 'nx*ny <= '//itoa(MAX_CHART_POINTS))
        end if

    contains

        !> One chart axis: finite min < max inside the range of its variable, 2..1000 points.
        subroutine chart_axis(ax, var, vmin, vmax, n)
            character(len=*), intent(in) :: ax      !! 'x' or 'y'
            character(len=*), intent(in) :: var     !! chart variable, lower case
            real(dp), intent(in) :: vmin, vmax      !! range
            integer, intent(in) :: n                !! number of points
            real(dp) :: lo, hi
            logical :: lo_in, hi_in
            character(len=:), allocatable :: desc, allowed
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'chart', ax//'_min', vmin)
            call finite(stat, 'chart', ax//'_max', vmax)
            if (stat%code /= STATUS_OK) return
            if (vmin >= vmax) then
                call bad(stat, 'chart', ax//'_max', rshort(vmax), 'not larger than '// &
                         ax//'_min = '//rshort(vmin), ax//'_min < '//ax//'_max')
                return
            end if
            ! allowed range lo .. hi of the variable, ends included when lo_in, hi_in
            lo = 0.0_dp
            hi = huge(1.0_dp)
            lo_in = .false.
            hi_in = .true.
            select case (trim(var))
            case ('l')
                desc = 'cable length l''/b'''
                lo = RATIO_MIN
                hi = RATIO_MAX
                if (sus%cables > 2) then
                    desc = 'every cable''s length, deck units'
                    lo = RATIO_MIN*sus%b_prime
                    hi = RATIO_MAX*sus%b_prime
                end if
                lo_in = .true.
            case ('radius')
                desc = 'the support''s radius, deck units; the body''s kept'
                lo = RATIO_MIN*sus%b_prime
                hi = RATIO_MAX*sus%b_prime
                lo_in = .true.
            case ('cg_offset', 'cg_depth')
                desc = 'deck units'
                lo = -RATIO_MAX*sus%b_prime
                hi = RATIO_MAX*sus%b_prime
                lo_in = .true.
            case ('b')
                desc = 'b/b'''
                lo = RATIO_MIN
                hi = RATIO_MAX
                lo_in = .true.
            case ('amplitude')
                desc = 'degrees'
                lo = FLOQUET_AMPLITUDE_MIN
                lo_in = .true.
                hi = 180.0_dp
                hi_in = .false.
            case ('r')
                desc = 'r/b'''
                hi = RATIO_MAX
                lo_in = .true.
            case ('lambda')
                desc = 'radians, -pi/2 .. pi/2'
                lo = -PI_HALF
                hi = PI_HALF
                lo_in = .true.
            case default
                desc = 'I3/I1'
                hi = RATIO_MAX
            end select
            allowed = rshort(lo)//trim(merge(' <=', ' < ', lo_in))//' '//ax//'_min < '// &
                ax//'_max'
            if (hi < huge(1.0_dp)) allowed = allowed//trim(merge(' <=', ' < ', hi_in))//' '// &
                rshort(hi)
            allowed = allowed//' for '//trim(var)//' ('//desc//')'
            if (vmin < lo .or. (vmin == lo .and. .not. lo_in)) then
                call bad(stat, 'chart', ax//'_min', rshort(vmin), 'outside the ' // &
                         'range of '//trim(var), allowed)
                return
            end if
            if (vmax > hi .or. (vmax == hi .and. .not. hi_in)) then
                call bad(stat, 'chart', ax//'_max', rshort(vmax), 'outside the ' // &
                         'range of '//trim(var), allowed)
                return
            end if
            if (n < 2 .or. n > MAX_CHART_N) then
                call bad(stat, 'chart', 'n'//ax, itoa(n), 'number of chart points ' // &
                         'out of range', '2 <= n'//ax//' <= '//itoa(MAX_CHART_N)// &
                         ' and nx*ny <= '//itoa(MAX_CHART_POINTS))
                return
            end if
        end subroutine chart_axis

    end procedure check_chart

    !> &design (checked when the analysis is requested; its lengths are in deck units):
    !! finite values; 0 < l_min < l_max with l over b' in RATIO_MIN .. RATIO_MAX and
    !! 2 <= nl <= MAX_CHART_N; b kept (b_min = b_max = 0, nb = 1), one b (b_min = b_max > 0,
    !! nb = 1) or 0 < b_min < b_max with 2 <= nb <= MAX_CHART_N, b over b' in range;
    !! 0 < amplitude_max <= 90 degrees, 1 <= n_amplitudes <= MAX_DESIGN_AMPLITUDES, the
    !! smallest amplitude amplitude_max/n_amplitudes >= FLOQUET_AMPLITUDE_MIN; at most
    !! MAX_CHART_POINTS Floquet points; each uncertainty >= 0 and below the value it
    !! qualifies (u_mass < mass, u_l < l_min, u_b below every b and b'; the period is only
    !! known when computed: the analysis checks u_period against it).
    module procedure check_design
        real(dp) :: bmin, am
        if (stat%code /= STATUS_OK) return
        if (sus%cables > 2) then
            ! a platform: its radius, not the bifilar's spacings
            if (self%b_min /= 0.0_dp .or. self%b_max /= 0.0_dp .or. self%nb /= 1 .or. &
                self%b_prime_min /= 0.0_dp .or. self%b_prime_max /= 0.0_dp .or. &
                self%nb_prime /= 1) then
                call bad(stat, 'design', 'b_min', rshort(self%b_min), 'a bifilar''s '// &
                         'spacings on a platform of '//itoa(sus%cables)//' cables', &
                         'radius_min, radius_max, nradius (the platform''s radius) with '// &
                         'cables >= 3')
                return
            end if
            call finite(stat, 'design', 'radius_min', self%radius_min)
            call finite(stat, 'design', 'radius_max', self%radius_max)
            if (stat%code /= STATUS_OK) return
            if (self%nradius == 1) then
                if (self%radius_min /= self%radius_max) then
                    call bad(stat, 'design', 'radius_max', rshort(self%radius_max), &
                             'differs from radius_min = '//rshort(self%radius_min)// &
                             ' with nradius = 1', 'radius_min = radius_max = 0 with '// &
                             'nradius = 1 (the deck''s radius), radius_min = radius_max > 0 '// &
                             'with nradius = 1, or 0 < radius_min < radius_max with '// &
                             'nradius >= 2')
                    return
                end if
                if (self%radius_min /= 0.0_dp) call positive(stat, 'design', 'radius_min', &
                    self%radius_min, 'radius_min = radius_max = 0 (the deck''s radius) or > 0')
            else if (self%nradius < 1 .or. self%nradius > MAX_CHART_N) then
                call bad(stat, 'design', 'nradius', itoa(self%nradius), 'number of radii '// &
                         'out of range', '1 <= nradius <= '//itoa(MAX_CHART_N))
                return
            else
                call positive(stat, 'design', 'radius_min', self%radius_min, &
                              '0 < radius_min < radius_max with nradius >= 2')
                if (stat%code /= STATUS_OK) return
                if (self%radius_min >= self%radius_max) call bad(stat, 'design', &
                    'radius_max', rshort(self%radius_max), 'not larger than radius_min = '// &
                    rshort(self%radius_min)//' with nradius = '//itoa(self%nradius), &
                    'radius_min < radius_max with nradius >= 2')
            end if
            if (stat%code /= STATUS_OK) return
            if (self%radius_min > 0.0_dp) then
                call over_b_prime(stat, 'design', 'radius_min', 2.0_dp*self%radius_min, &
                                  sus%b_prime, RATIO_MIN)
                call over_b_prime(stat, 'design', 'radius_max', 2.0_dp*self%radius_max, &
                                  sus%b_prime, RATIO_MIN)
                if (stat%code /= STATUS_OK) return
            end if
        else if (self%radius_min /= 0.0_dp .or. self%radius_max /= 0.0_dp .or. &
                 self%nradius /= 1) then
            call bad(stat, 'design', 'radius_min', rshort(self%radius_min), 'a platform''s '// &
                     'radius on a bifilar', 'b_min, b_max, nb and b_prime_min, '// &
                     'b_prime_max, nb_prime with cables = 2')
            return
        end if
        call positive(stat, 'design', 'l_min', self%l_min, '0 < l_min < l_max (deck units)')
        call positive(stat, 'design', 'l_max', self%l_max, '0 < l_min < l_max (deck units)')
        if (stat%code /= STATUS_OK) return
        if (self%l_min >= self%l_max) then
            call bad(stat, 'design', 'l_max', rshort(self%l_max), 'not larger than '// &
                     'l_min = '//rshort(self%l_min), 'l_min < l_max')
            return
        end if
        call over_b_prime(stat, 'design', 'l_min', self%l_min, sus%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'design', 'l_max', self%l_max, sus%b_prime, RATIO_MIN)
        if (stat%code /= STATUS_OK) return
        if (self%nl < 2 .or. self%nl > MAX_CHART_N) then
            call bad(stat, 'design', 'nl', itoa(self%nl), 'number of cable lengths '// &
                     'out of range', '2 <= nl <= '//itoa(MAX_CHART_N))
            return
        end if
        call finite(stat, 'design', 'b_min', self%b_min)
        call finite(stat, 'design', 'b_max', self%b_max)
        if (stat%code /= STATUS_OK) return
        if (self%nb == 1) then
            if (self%b_min /= self%b_max) then
                call bad(stat, 'design', 'b_max', rshort(self%b_max), 'differs from '// &
                         'b_min = '//rshort(self%b_min)//' with nb = 1', 'b_min = '// &
                         'b_max = 0 with nb = 1 (the deck''s b), b_min = b_max > 0 with '// &
                         'nb = 1 (that b), or 0 < b_min < b_max with nb >= 2')
                return
            end if
            if (self%b_min /= 0.0_dp) call positive(stat, 'design', 'b_min', &
                self%b_min, 'b_min = b_max = 0 (the deck''s b) or > 0')
        else if (self%nb < 1 .or. self%nb > MAX_CHART_N) then
            call bad(stat, 'design', 'nb', itoa(self%nb), 'number of support spacings '// &
                     'out of range', '1 <= nb <= '//itoa(MAX_CHART_N))
            return
        else
            call positive(stat, 'design', 'b_min', self%b_min, '0 < b_min < b_max '// &
                          'with nb >= 2')
            if (stat%code /= STATUS_OK) return
            if (self%b_min >= self%b_max) call bad(stat, 'design', 'b_max', &
                rshort(self%b_max), 'not larger than b_min = '//rshort(self%b_min)// &
                ' with nb = '//itoa(self%nb), 'b_min < b_max with nb >= 2')
        end if
        if (stat%code /= STATUS_OK) return
        if (self%b_min > 0.0_dp) then
            call over_b_prime(stat, 'design', 'b_min', self%b_min, sus%b_prime, RATIO_MIN)
            call over_b_prime(stat, 'design', 'b_max', self%b_max, sus%b_prime, RATIO_MIN)
        end if
        ! the body's spacing b', as b
        call finite(stat, 'design', 'b_prime_min', self%b_prime_min)
        call finite(stat, 'design', 'b_prime_max', self%b_prime_max)
        if (stat%code /= STATUS_OK) return
        if (self%nb_prime == 1) then
            if (self%b_prime_min /= self%b_prime_max) then
                call bad(stat, 'design', 'b_prime_max', rshort(self%b_prime_max), &
                         'differs from b_prime_min = '//rshort(self%b_prime_min)// &
                         ' with nb_prime = 1', 'b_prime_min = b_prime_max = 0 with '// &
                         'nb_prime = 1 (the deck''s b_prime), b_prime_min = b_prime_max > 0 '// &
                         'with nb_prime = 1 (that b_prime), or 0 < b_prime_min < b_prime_max '// &
                         'with nb_prime >= 2')
                return
            end if
            if (self%b_prime_min /= 0.0_dp) call positive(stat, 'design', 'b_prime_min', &
                self%b_prime_min, 'b_prime_min = b_prime_max = 0 (the deck''s b_prime) '// &
                'or > 0')
        else if (self%nb_prime < 1 .or. self%nb_prime > MAX_CHART_N) then
            call bad(stat, 'design', 'nb_prime', itoa(self%nb_prime), 'number of body '// &
                     'spacings out of range', '1 <= nb_prime <= '//itoa(MAX_CHART_N))
            return
        else
            call positive(stat, 'design', 'b_prime_min', self%b_prime_min, &
                          '0 < b_prime_min < b_prime_max with nb_prime >= 2')
            if (stat%code /= STATUS_OK) return
            if (self%b_prime_min >= self%b_prime_max) call bad(stat, 'design', &
                'b_prime_max', rshort(self%b_prime_max), 'not larger than b_prime_min = '// &
                rshort(self%b_prime_min)//' with nb_prime = '//itoa(self%nb_prime), &
                'b_prime_min < b_prime_max with nb_prime >= 2')
        end if
        if (stat%code /= STATUS_OK) return
        if (self%b_prime_min > 0.0_dp) then
            call over_b_prime(stat, 'design', 'b_prime_min', self%b_prime_min, sus%b_prime, &
                              RATIO_MIN)
            call over_b_prime(stat, 'design', 'b_prime_max', self%b_prime_max, sus%b_prime, &
                              RATIO_MIN)
            if (stat%code /= STATUS_OK) return
            if (self%b_prime_min <= 2.0_dp*abs(bod%cg_offset)) call bad(stat, 'design', &
                'b_prime_min', rshort(self%b_prime_min), 'does not reach past the mass '// &
                'centre''s offset (cg_offset = '//rshort(bod%cg_offset)//')', &
                'b_prime_min > 2 |cg_offset|')
        end if
        call finite(stat, 'design', 'amplitude_max', self%amplitude_max)
        if (stat%code /= STATUS_OK) return
        if (self%amplitude_max <= 0.0_dp .or. self%amplitude_max > 90.0_dp) then
            call bad(stat, 'design', 'amplitude_max', rshort(self%amplitude_max), &
                     'out of range', '0 < amplitude_max <= 90 (degrees of theta4)')
            return
        end if
        if (self%n_amplitudes < 1 .or. self%n_amplitudes > MAX_DESIGN_AMPLITUDES) then
            call bad(stat, 'design', 'n_amplitudes', itoa(self%n_amplitudes), &
                     'number of amplitudes out of range', '1 <= n_amplitudes <= '// &
                     itoa(MAX_DESIGN_AMPLITUDES))
            return
        end if
        ! the amplitude of measurement the analysis takes (normalise)
        am = self%measure_amplitude()
        call finite(stat, 'design', 'amplitude_measure', am)
        if (stat%code /= STATUS_OK) return
        if (am <= 0.0_dp .or. &
            am > self%amplitude_max) then
            call bad(stat, 'design', 'amplitude_measure', rshort(am), &
                     'out of range', '0 < amplitude_measure <= amplitude_max = '// &
                     rshort(self%amplitude_max)//' (degrees of theta4: the amplitude of '// &
                     'the measurement, within the stability checked)')
            return
        end if
        if (self%amplitude_max/self%n_amplitudes < FLOQUET_AMPLITUDE_MIN) then
            call bad(stat, 'design', 'amplitude_max', rshort(self%amplitude_max), &
                     'its smallest amplitude amplitude_max/n_amplitudes is below '// &
                     rshort(FLOQUET_AMPLITUDE_MIN)//' degrees', 'amplitude_max/n_amplitudes'// &
                     ' >= '//rshort(FLOQUET_AMPLITUDE_MIN)//' (degrees of theta4)')
            return
        end if
        if (real(self%nl, dp)*self%nb*self%nb_prime*self%n_amplitudes > &
            MAX_CHART_POINTS) then
            call bad(stat, 'design', 'n_amplitudes', itoa(self%n_amplitudes), &
                     'too many Floquet points (nl*nb*n_amplitudes = '// &
                     sci(real(self%nl, dp)*self%nb*self%n_amplitudes)//')', &
                     'nl*nb*n_amplitudes <= '//itoa(MAX_CHART_POINTS))
            return
        end if
        bmin = min(sus%b_prime, sus%b)
        if (self%b_min > 0.0_dp) bmin = min(sus%b_prime, self%b_min)
        call uncertainty('u_mass', self%u_mass, bod%mass, 'the mass')
        call uncertainty('u_l', self%u_l, self%l_min, 'l_min')
        call uncertainty('u_b', self%u_b, bmin, 'every b and b_prime')
        call uncertainty('u_period', self%u_period, huge(1.0_dp), '')

    contains

        !> A standard uncertainty: finite, >= 0, below the value it qualifies.
        subroutine uncertainty(var, u, x, what)
            character(len=*), intent(in) :: var     !! its name
            real(dp), intent(in) :: u, x            !! the uncertainty and its value
            character(len=*), intent(in) :: what    !! the value's name ('' for none)
            character(len=:), allocatable :: allowed
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'design', var, u)
            if (stat%code /= STATUS_OK) return
            allowed = '0 <= '//var
            if (len(what) > 0) allowed = allowed//' < '//what//' ('//rshort(x)//')'
            allowed = allowed//', a standard uncertainty in deck units'
            if (var == 'u_period') allowed = allowed//' (s)'
            if (u < 0.0_dp) then
                call bad(stat, 'design', var, rshort(u), 'a negative uncertainty', allowed)
            else if (len(what) > 0 .and. u >= x) then
                call bad(stat, 'design', var, rshort(u), 'not below the value it qualifies', &
                         allowed)
            end if
        end subroutine uncertainty

    end procedure check_design

    !> &output columns: blank-separated names from `cols` (any case), at least one, none
    !! twice (normalise puts them in the order of cols).
    subroutine check_columns(stat, columns, cols, whose)
        type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
        character(len=*), intent(in) :: columns     !! value read
        character(len=*), intent(in) :: cols        !! the names allowed, in their order
        character(len=*), intent(in) :: whose       !! whose columns they are ('' a bifilar's)
        character(len=len(columns)) :: list
        character(len=len(cols)) :: known
        logical :: asked(count_words(cols))
        integer :: i1, i2, j1, j2, n
        character(len=:), allocatable :: head, allowed
        list = columns
        do i1 = 1, len(list)
            if (list(i1:i1) == achar(9)) list(i1:i1) = ' '
        end do
        known = lower(cols)
        head = '&output columns = '''//trim(adjustl(list))//''': '
        allowed = 'allowed: blank-separated names, in any order and case, from'//whose//': '// &
            commas(cols)
        asked = .false.
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            j2 = 0
            n = 0
            do
                call next_word(known, j2, j1)
                if (j1 == 0) exit
                n = n + 1
                if (known(j1:j2) == lower(list(i1:i2))) exit
            end do
            if (j1 == 0) then
                call set_error(stat, ERR_DECK, head//'unknown column '''//list(i1:i2)// &
                               '''; '//allowed)
                return
            end if
            if (asked(n)) then
                call set_error(stat, ERR_DECK, head//'column '''//list(i1:i2)// &
                               ''' given twice; '//allowed)
                return
            end if
            asked(n) = .true.
        end do
        if (.not. any(asked)) then
            call set_error(stat, ERR_DECK, head//'no column given; '//allowed)
            return
        end if
    end subroutine check_columns

    !> Every word of &scene analyses must be known; at least one word.
    subroutine check_analyses(stat, analyses)
        type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
        character(len=*), intent(in) :: analyses    !! value read
        character(len=len(analyses)) :: list
        integer :: i1, i2
        character(len=:), allocatable :: head
        list = lower(analyses)
        head = '&scene analyses = '''//clip(trim(analyses))//''': '
        if (len_trim(list) > 256) then
            call set_error(stat, ERR_DECK, head//'longer than 256 characters; allowed: '// &
                           'blank-separated words from: '//commas(ANALYSES_ALLOWED))
            return
        end if
        if (len_trim(list) == 0) then
            call set_error(stat, ERR_DECK, head//'no analysis given; allowed: '// &
                           'blank-separated words from: '//commas(ANALYSES_ALLOWED))
            return
        end if
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            if (index(' '//ANALYSES_ALLOWED//' ', ' '//list(i1:i2)//' ') == 0) then
                call set_error(stat, ERR_DECK, head//'unknown analysis '''// &
                               analyses(i1:i2)//'''; allowed: blank-separated words from: '// &
                               commas(ANALYSES_ALLOWED))
                return
            end if
        end do
    end subroutine check_analyses

end submodule analysis_checks
