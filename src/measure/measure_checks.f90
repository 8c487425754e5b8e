!> The checks of the measurements' groups (submodule of measure_groups): each value finite
!! and in its range, words known, each standard uncertainty inside its input's domain (the
!! rig's groups: the suspension as normalised, the body as given), the first problem an
!! ERR_DECK status naming the group, the variable, its value, what is wrong and what is
!! allowed.  A check never changes a value (the words it compares in lower case, the
!! u_inertia the run takes, are made here, as normalise makes them).  Each returns at once
!! when an earlier check failed.
submodule (measure_groups) measure_checks
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: next_word, commas, clip
    use value_checks, only: bad, finite, positive, dimensional, in_domain, check_word, DIM_MAX
    implicit none

contains

    !> &measurement: periods given without gaps, each finite, > 0 and at most DIM_MAX, one
    !! amplitude (0 < a < 180 degrees) per period and no more; uncertainties finite, >= 0
    !! and at most DIM_MAX; 0 or 2 .. MAX_MONTE_CARLO Monte Carlo samples.  (quantity and
    !! estimate are checked by read_deck; what identify needs of them, by identify_ready.)
    module procedure check_measurement
        integer :: i, na, nc
        character(len=16) :: nm
        logical :: unit_rate
        character(len=len(self%quantity)) :: quantity
        character(len=len(self%record_units)) :: units
        real(dp) :: u_inertia(2)
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'measurement', 'quantity', self%quantity, QUANTITIES_ALLOWED)
        if (stat%code /= STATUS_OK) return
        call check_estimate(stat, self%estimate)
        if (stat%code /= STATUS_OK) return
        quantity = lower(adjustl(self%quantity))
        do i = self%n_periods + 1, MAX_PERIODS
            if (self%periods(i) /= PERIOD_UNSET) then
                call bad(stat, 'measurement', 'periods('//itoa(i)//')', rshort(self%periods(i)), &
                         'given after a period left out (periods('//itoa(self%n_periods + 1)// &
                         '))', 'periods(1), periods(2), ... without gaps, at most '// &
                         itoa(MAX_PERIODS))
                return
            end if
        end do
        na = 0
        do while (na < MAX_PERIODS)
            if (self%amplitudes(na + 1) == PERIOD_UNSET) exit
            na = na + 1
        end do
        do i = na + 1, MAX_PERIODS
            if (self%amplitudes(i) /= PERIOD_UNSET) then
                call bad(stat, 'measurement', 'amplitudes('//itoa(i)//')', &
                         rshort(self%amplitudes(i)), 'given after an amplitude left out '// &
                         '(amplitudes('//itoa(na + 1)//'))', 'one amplitude per period, '// &
                         'without gaps')
                return
            end if
        end do
        if (na /= self%n_periods) then
            call bad(stat, 'measurement', 'amplitudes', itoa(na)//' values', 'there are '// &
                     itoa(self%n_periods)//' periods', 'one amplitude (degrees of theta4 at '// &
                     'the peak) per period')
            return
        end if
        do i = 1, self%n_periods
            nm = 'periods('//itoa(i)//')'
            call positive(stat, 'measurement', trim(nm), self%periods(i), 'periods > 0 (s)')
            call dimensional(stat, 'measurement', trim(nm), self%periods(i))
            nm = 'amplitudes('//itoa(i)//')'
            call finite(stat, 'measurement', trim(nm), self%amplitudes(i))
            if (stat%code /= STATUS_OK) return
            if (self%amplitudes(i) < AMPLITUDE_MIN .or. self%amplitudes(i) >= 180.0_dp) then
                call bad(stat, 'measurement', trim(nm), rshort(self%amplitudes(i)), &
                         'out of range', rshort(AMPLITUDE_MIN)//' <= amplitude < 180 '// &
                         '(degrees of theta4 at the peak; smaller swings the model does '// &
                         'not resolve)')
                return
            end if
        end do
        call uncertainty('u_mass', self%u_mass)
        call uncertainty('u_l', self%u_l)
        call uncertainty('u_l_prime', self%u_l_prime)
        call uncertainty('u_b', self%u_b)
        call uncertainty('u_b_prime', self%u_b_prime)
        call uncertainty('u_g', self%u_g)
        call uncertainty('u_period', self%u_period)
        call uncertainty('u_amplitude', self%u_amplitude)
        call uncertainty('u_amplitude_scale', self%u_amplitude_scale)
        if (stat%code /= STATUS_OK) return
        if (self%u_amplitude_scale > 0.5_dp) then
            call bad(stat, 'measurement', 'u_amplitude_scale', rshort(self%u_amplitude_scale), &
                     'above 0.5', 'a relative standard uncertainty of the amplitudes'' '// &
                     'scale, 0 .. 0.5 (0.014 for 1.4 %)')
            return
        end if
        ! cycles: none (1 each), one value for every period, or one per period
        nc = count(self%cycles /= PERIOD_UNSET)
        if (nc > 0) then
            if (any(self%cycles(nc + 1:) /= PERIOD_UNSET)) then
                call bad(stat, 'measurement', 'cycles', 'with a gap', 'a value given after '// &
                         'one left out', 'cycles = N (every period the time of N cycles) or '// &
                         'one value per period, without gaps')
                return
            end if
            if (nc /= 1 .and. nc /= self%n_periods) then
                call bad(stat, 'measurement', 'cycles', itoa(nc)//' values', 'there are '// &
                         itoa(self%n_periods)//' periods', 'cycles = N (every period the '// &
                         'time of N cycles) or one value per period')
                return
            end if
            do i = 1, nc
                call finite(stat, 'measurement', 'cycles('//itoa(i)//')', self%cycles(i))
                if (stat%code /= STATUS_OK) return
                if (self%cycles(i) < 0.5_dp .or. self%cycles(i) > 1.0e6_dp) then
                    call bad(stat, 'measurement', 'cycles('//itoa(i)//')', rshort(self%cycles(i)), &
                             'out of range', '0.5 <= cycles <= 1e6 (the number of cycles the '// &
                             'period''s time spans)')
                    return
                end if
            end do
        end if
        ! the record's columns and units
        call finite(stat, 'measurement', 'record_frame_rate', self%record_frame_rate)
        if (stat%code /= STATUS_OK) return
        if (self%record_frame_rate < 0.0_dp .or. self%record_frame_rate > 1.0e6_dp) then
            call bad(stat, 'measurement', 'record_frame_rate', rshort(self%record_frame_rate), &
                     'out of range', '0 (times in s) or 0 < record_frame_rate <= 1e6 (frames '// &
                     'a second: the time column holds frame numbers)')
            return
        end if
        if (self%gave('record_columns')) call check_record_columns()
        if (stat%code /= STATUS_OK) return
        if (len_trim(self%record_units) > 0) then
            call check_word(stat, 'measurement', 'record_units', self%record_units, &
                            RECORD_UNITS_ALLOWED)
            if (stat%code /= STATUS_OK) return
            units = lower(adjustl(self%record_units))
            unit_rate = index(units, '/s') > 0
            if (self%gave('quantity') .and. ((trim(quantity) == 'rate' .or. &
                                               trim(quantity) == 'rates') .neqv. unit_rate)) then
                call bad(stat, 'measurement', 'record_units', quoted(units), &
                         'a '//trim(merge('rate ', 'angle', unit_rate))//' with quantity = '// &
                         quoted(quantity), 'rad or deg with quantity = ''angle'', rad/s or '// &
                         'deg/s with quantity = ''rate'' (or leave quantity out: the units '// &
                         'imply it)')
                return
            end if
        end if
        call check_word(stat, 'measurement', 'loss', self%loss, LOSSES_ALLOWED)
        if (stat%code /= STATUS_OK) return
        ! quantity 'rates': the instrument's axes
        block
            real(dp) :: axes(3, 3)
            logical :: ok
            call parse_axes(lower(self%record_axes), axes, ok)
            if (.not. ok) then
                call bad(stat, 'measurement', 'record_axes', quoted(trim(self%record_axes)), &
                         'not the instrument''s axes', '''aligned'' (its x, y, z along the '// &
                         'body''s principal axes b_1, b_2, b_3) or three signed letters, the '// &
                         'body axis along its x, y and z in turn, each once, e.g. ''z -y x''')
                return
            end if
        end block
        call check_point()
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'measurement', 'on_failure', self%on_failure, ON_FAILURE_ALLOWED)
        if (stat%code /= STATUS_OK) return
        if (len_trim(self%session) > 64) then
            call bad(stat, 'measurement', 'session', quoted(clip(self%session)), &
                     'longer than 64 characters', 'a label of 1 to 64 characters')
            return
        end if
        if (self%n_periods > 0 .and. len_trim(self%trials) > 0) then
            call bad(stat, 'measurement', 'trials', quoted(self%trials), 'given with periods', &
                     'periods (one release) or trials = ''FILE'' (a table of releases), not '// &
                     'both')
            return
        end if
        if (len_trim(self%record) > 0 .and. len_trim(self%trials) > 0) then
            call bad(stat, 'measurement', 'trials', quoted(self%trials), 'given with record', &
                     'record (one release) or trials = ''FILE'' (a table of releases, with a '// &
                     'column record), not both')
            return
        end if
        u_inertia = self%u_inertia_of()
        call uncertainty('u_inertia', u_inertia(1))
        call uncertainty('u_inertia', u_inertia(2))
        call uncertainty('u_cg_depth', self%u_cg_depth)
        call uncertainty('u_cg_offset', self%u_cg_offset)
        call uncertainty('u_r', self%u_r)
        call uncertainty('u_lambda', self%u_lambda)
        call uncertainty('u_tare_i1', self%u_tare_i1)
        call uncertainty('u_added_inertia', self%u_added_inertia)
        call uncertainty('tare_i1', self%tare_i1)
        call uncertainty('added_inertia', self%added_inertia)
        call uncertainty('tare_mass', self%tare_mass)
        if (stat%code /= STATUS_OK) return
        if ((self%u_cg_depth > 0.0_dp .or. self%u_cg_offset > 0.0_dp) .and. .not. &
            (bod%gave('cg_depth') .or. bod%gave('cg_offset') .or. sus%cables > 2)) then
            call bad(stat, 'measurement', trim(merge('u_cg_depth ', 'u_cg_offset', &
                     self%u_cg_depth > 0.0_dp)), rshort(max(self%u_cg_depth, self%u_cg_offset)), &
                     'the mass centre is given as r, lambda', 'u_r, u_lambda with r, lambda; '// &
                     'u_cg_depth, u_cg_offset with cg_depth, cg_offset')
            return
        end if
        if ((self%u_r > 0.0_dp .or. self%u_lambda > 0.0_dp) .and. (bod%gave('cg_depth') .or. &
            bod%gave('cg_offset') .or. sus%cables > 2)) then
            call bad(stat, 'measurement', trim(merge('u_r     ', 'u_lambda', self%u_r > 0.0_dp)), &
                     rshort(max(self%u_r, self%u_lambda)), 'the mass centre is given as '// &
                     'cg_depth, cg_offset', 'u_cg_depth, u_cg_offset with cg_depth, '// &
                     'cg_offset; u_r, u_lambda with r, lambda')
            return
        end if
        if (self%u_l_prime > 0.0_dp .and. sus%cables > 2) then
            ! a platform's cables are one input, l (u_l); u_l_prime would be left out
            call bad(stat, 'measurement', 'u_l_prime', rshort(self%u_l_prime), 'a platform of '// &
                     itoa(sus%cables)//' cables has no second cable length l_prime (its '// &
                     'lengths are one input, l)', 'u_l for the cables'' length on a '// &
                     'platform; u_l_prime on a bifilar rig (cables = 2)')
            return
        end if
        ! a u whose 5-sigma range leaves its input's domain: the Monte Carlo would draw
        ! values no rig has (l < 0, g < 0, an amplitude beyond 180 degrees), the budget's
        ! steps would cross the edge
        call in_domain(stat, 'measurement', 'u_mass', self%u_mass, 'mass', bod%mass, 0.0_dp, &
                       0.0_dp)
        call in_domain(stat, 'measurement', 'u_l', self%u_l, 'l', sus%l, 0.0_dp, 0.0_dp)
        if (sus%cables == 2) call in_domain(stat, 'measurement', 'u_l_prime', self%u_l_prime, &
                                          'l_prime', sus%l_prime, 0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_b', self%u_b, 'b', sus%b, 0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_b_prime', self%u_b_prime, 'b_prime', sus%b_prime, &
                       0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_g', self%u_g, 'g', sus%g, 0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_inertia', u_inertia(1), 'inertia(2)', &
                       bod%inertia(2), 0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_inertia', u_inertia(2), 'inertia(3)', &
                       bod%inertia(3), 0.0_dp, 0.0_dp)
        if (.not. (bod%gave('cg_depth') .or. bod%gave('cg_offset') .or. sus%cables > 2)) &
            call in_domain(stat, 'measurement', 'u_r', self%u_r, 'r', bod%r, 0.0_dp, 0.0_dp, .true.)
        do i = 1, self%n_periods
            call in_domain(stat, 'measurement', 'u_period', self%u_period, 'periods('//itoa(i)// &
                           ')', self%periods(i), 0.0_dp, 0.0_dp)
            ! the period depends on |amplitude|: only 180 degrees bounds its draws
            call in_domain(stat, 'measurement', 'u_amplitude', self%u_amplitude, 'amplitudes('// &
                           itoa(i)//')', self%amplitudes(i), -180.0_dp, 180.0_dp)
        end do
        if (len_trim(self%record) > 0 .and. trim(sta%mode) == 'raised' .and. .not. &
            self%estimated('amplitude')) call in_domain(stat, 'measurement', 'u_amplitude', &
            self%u_amplitude, 'the release amplitude (&start amplitude)', sta%amplitude, 0.0_dp, &
            180.0_dp)
        if (stat%code /= STATUS_OK) return
        if (self%tare_mass >= bod%mass) then
            call bad(stat, 'measurement', 'tare_mass', rshort(self%tare_mass), 'not below the '// &
                     'mass of the whole rig (&body mass = '//rshort(bod%mass)//')', '0 <= '// &
                     'tare_mass < mass (the fixture''s mass; &body mass is the total hung)')
            return
        end if
        if (self%monte_carlo == 1 .or. self%monte_carlo < 0 .or. &
            self%monte_carlo > MAX_MONTE_CARLO) &
            call bad(stat, 'measurement', 'monte_carlo', itoa(self%monte_carlo), &
                     'number of Monte Carlo samples out of range', '0 (first order only) '// &
                     'or 2 <= monte_carlo <= '//itoa(MAX_MONTE_CARLO))
    contains
        !> quantity 'point': the tracked point given (record_point), the view a word of
        !! VIEWS_ALLOWED, the record's scale > 0; estimate = 'scale' not with the amplitude of
        !! a record of one value (the two only change the swing's size together).
        subroutine check_point()
            call check_word(stat, 'measurement', 'record_view', self%record_view, VIEWS_ALLOWED)
            if (stat%code /= STATUS_OK) return
            call positive(stat, 'measurement', 'record_scale', self%record_scale, &
                          'the length of one unit of the record''s columns (m, e.g. m/px), '// &
                          '> 0 (1: the columns are metres)')
            if (stat%code /= STATUS_OK) return
            if (trim(quantity) == 'point') then
                if (any(self%record_point == PERIOD_UNSET)) then
                    call bad(stat, 'measurement', 'record_point', 'not given', &
                             'quantity = ''point'' tracks a point of the body', 'record_point '// &
                             '= x, y, z: the point in the body''s principal axes from the mass '// &
                             'centre (m), e.g. record_point = 0, 0.05, 0')
                    return
                end if
                do i = 1, 3
                    call finite(stat, 'measurement', 'record_point('//itoa(i)//')', &
                                self%record_point(i))
                end do
                if (stat%code /= STATUS_OK) return
                if (sus%cables > 2) then
                    call bad(stat, 'measurement', 'quantity', '''point''', 'with a platform '// &
                             'of '//itoa(sus%cables)//' cables', 'quantity = ''point'' with a '// &
                             'bifilar (2 cables); a platform''s record as angle or rate')
                    return
                end if
            end if
            if (trim(quantity) == 'rates' .and. sus%cables > 2) then
                ! the platform's models give the yaw and the rate about the vertical only
                call bad(stat, 'measurement', 'quantity', '''rates''', 'with a platform of '// &
                         itoa(sus%cables)//' cables', 'quantity = ''rates'' with a bifilar '// &
                         '(2 cables); a platform''s record as angle or rate')
                return
            end if
            if (self%estimated('scale') .and. self%estimated('amplitude') .and. &
                trim(quantity) /= 'point' .and. trim(quantity) /= 'rates') then
                call bad(stat, 'measurement', 'estimate', quoted(trim(self%estimate)), &
                         'the record cannot separate scale and amplitude (a record of one '// &
                         'value: both only change the swing''s size)', 'estimate one of them, '// &
                         'or quantity = ''point'' or ''rates''')
            end if
        end subroutine check_point
        !> record_columns: numbers (1 .. 100) or names of the header's columns, the value's
        !! given, the time's too unless record_frame_rate gives the time from the row; no
        !! column twice; a name that starts as a number does but is none refused.
        subroutine check_record_columns()
            integer :: k, j
            character(len=:), allocatable :: given
            logical :: named(4), used(4)
            associate (rc => self%record_columns, nm => self%record_column_names)
                named = rc == 0 .and. len_trim(nm) > 0
                used = rc > 0 .or. named
                given = column_list()
                if (lower(adjustl(self%quantity)) == 'point') then
                    ! time (or record_frame_rate) and the track's x, y, distinct, no fourth
                    do k = 1, 3
                        if (rc(k) > 100 .or. (named(k) .and. scan(nm(k)(1:1), &
                                                                  '0123456789+-.') > 0)) &
                            used(k) = .false.
                        do j = k + 1, 3
                            if ((rc(k) > 0 .and. rc(k) == rc(j)) .or. (named(k) .and. &
                                named(j) .and. nm(k) == nm(j))) used(j) = .false.
                        end do
                    end do
                    if (.not. all(used(2:3)) .or. used(4) .or. (.not. used(1) .and. .not. &
                        self%record_frame_rate > 0.0_dp)) call bad(stat, 'measurement', &
                        'record_columns', given, 'not three distinct columns with quantity '// &
                        '= ''point''', 'record_columns = T, X, Y: the time (s) and the '// &
                        'point''s two coordinates (px), numbers 1 .. 100 or names of the '// &
                        'header''s columns (the time may be 0 with record_frame_rate)')
                    return
                end if
                if (lower(adjustl(self%quantity)) == 'rates') then
                    ! time (or record_frame_rate) and the instrument's x, y, z, distinct
                    do k = 1, 4
                        if (rc(k) > 100 .or. (named(k) .and. scan(nm(k)(1:1), &
                                                                  '0123456789+-.') > 0)) &
                            used(k) = .false.
                        do j = k + 1, 4
                            if ((rc(k) > 0 .and. rc(k) == rc(j)) .or. (named(k) .and. &
                                named(j) .and. nm(k) == nm(j))) used(j) = .false.
                        end do
                    end do
                    if (.not. all(used(2:4)) .or. (.not. used(1) .and. .not. &
                        self%record_frame_rate > 0.0_dp)) call bad(stat, 'measurement', &
                        'record_columns', given, 'not four distinct columns with quantity '// &
                        '= ''rates''', 'record_columns = T, X, Y, Z: the time (s) and the '// &
                        'instrument''s rates about its x, y, z, numbers 1 .. 100 or names '// &
                        'of the header''s columns (the time may be left out with '// &
                        'record_frame_rate)')
                    return
                end if
                if (used(4)) then
                    call bad(stat, 'measurement', 'record_columns', given, 'a fourth '// &
                             'column', 'four columns (time, x, y, z) with quantity = '// &
                             '''rates''; else record_columns = T, V or T, V, U')
                    return
                end if
                if (all(.not. named)) then
                    ! numbers alone: as always, but the time's may be left out with a frame rate
                    if (rc(2) < 1 .or. (rc(1) < 1 .and. .not. self%record_frame_rate > 0.0_dp) &
                        .or. any(rc > 100) .or. (rc(1) > 0 .and. rc(1) == rc(2)) .or. &
                        (rc(3) > 0 .and. (rc(3) == rc(1) .or. rc(3) == rc(2)))) then
                        if (rc(1) < 1 .and. rc(2) >= 1 .and. rc(2) <= 100 .and. rc(3) /= rc(2) &
                            .and. rc(3) <= 100) then
                            call bad(stat, 'measurement', 'record_columns', given, 'no time '// &
                                     'column, and no record_frame_rate', 'a time column '// &
                                     '(record_columns = T, V), or record_frame_rate = F '// &
                                     '(frames a second: the time of row i is (i - 1)/F)')
                        else
                            call bad(stat, 'measurement', 'record_columns', given, &
                                     'not three distinct columns', 'record_columns = T, V or '// &
                                     'T, V, U: the 1-based columns of time (s), value and '// &
                                     'each sample''s standard uncertainty, distinct, at most '// &
                                     '100 (or their names in the header)')
                        end if
                    end if
                    return
                end if
                do k = 1, 3
                    if (.not. named(k)) cycle
                    if (scan(nm(k)(1:1), '0123456789+-.') > 0) then
                        call bad(stat, 'measurement', 'record_columns', given, &
                                 quoted(nm(k))//' is neither a column''s number nor a name', &
                                 'record_columns = T, V or T, V, U: whole numbers 1 .. 100 '// &
                                 'or names of the header''s columns, e.g. ''Time (s)'', '// &
                                 '''Gyroscope z (rad/s)''')
                        return
                    end if
                end do
                if (.not. used(2) .or. (.not. used(1) .and. .not. self%record_frame_rate > &
                    0.0_dp)) then
                    call bad(stat, 'measurement', 'record_columns', given, 'no '// &
                             trim(merge('value', 'time ', .not. used(2)))//' column', &
                             'record_columns = T, V or T, V, U (numbers or names), or V '// &
                             'alone with record_frame_rate = F (the time of row i is '// &
                             '(i - 1)/F)')
                    return
                end if
                do k = 1, 3
                    if (rc(k) > 100) then
                        call bad(stat, 'measurement', 'record_columns', given, 'column '// &
                                 itoa(rc(k))//' beyond 100', 'columns 1 .. 100, or names')
                        return
                    end if
                    do j = k + 1, 3
                        if ((rc(k) > 0 .and. rc(k) == rc(j)) .or. (named(k) .and. named(j) &
                            .and. nm(k) == nm(j))) then
                            call bad(stat, 'measurement', 'record_columns', given, 'a column '// &
                                     'given twice', 'distinct columns of time, value and '// &
                                     'each sample''s standard uncertainty')
                            return
                        end if
                    end do
                end do
            end associate
        end subroutine check_record_columns
        !> record_columns as given, for a message.
        function column_list() result(c)
            character(len=:), allocatable :: c
            integer :: k
            c = ''
            do k = 1, merge(4, 3, self%record_columns(4) > 0 .or. &
                            len_trim(self%record_column_names(4)) > 0)
                if (k > 1) c = c//', '
                if (self%record_columns(k) == 0 .and. len_trim(self%record_column_names(k)) > 0) &
                    then
                    c = c//quoted(self%record_column_names(k))
                else
                    c = c//itoa(self%record_columns(k))
                end if
            end do
        end function column_list
        subroutine uncertainty(var, x)
            character(len=*), intent(in) :: var
            real(dp), intent(in) :: x
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'measurement', var, x)
            if (stat%code /= STATUS_OK) return
            if (x < 0.0_dp .or. x > DIM_MAX) call bad(stat, 'measurement', var, rshort(x), &
                'a standard uncertainty out of range', '0 <= '//var//' <= '// &
                rshort(DIM_MAX)//' (deck units; 0: not known)')
        end subroutine uncertainty
    end procedure check_measurement

    !> &measurement estimate (or a release's): blank-separated words from ESTIMATES_ALLOWED
    !! (I1 in any case, the others in lower case too), at least one, none twice.
    module procedure check_estimate
        character(len=len(estimate)) :: list
        integer :: i1, i2, n
        character(len=:), allocatable :: hd, allowed, seen
        list = lower(estimate)
        do i1 = 1, len(list)
            if (list(i1:i1) == achar(9)) list(i1:i1) = ' '
        end do
        if (present(head)) then
            hd = head
        else
            hd = '&measurement estimate = '''//clip(trim(adjustl(estimate)))//''': '
        end if
        allowed = 'allowed: blank-separated words from: '//commas(ESTIMATES_ALLOWED)
        seen = ' '
        n = 0
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            n = n + 1
            if (index(' '//lower(ESTIMATES_ALLOWED)//' ', ' '//list(i1:i2)//' ') == 0) then
                call set_error(stat, ERR_DECK, hd//'unknown word '''//clip(list(i1:i2))// &
                               '''; '//allowed)
                return
            end if
            if (index(seen, ' '//list(i1:i2)//' ') > 0) then
                call set_error(stat, ERR_DECK, hd//''''//list(i1:i2)//''' given twice; '// &
                               allowed)
                return
            end if
            seen = seen//list(i1:i2)//' '
        end do
        if (n == 0) call set_error(stat, ERR_DECK, hd//'no parameter given; '//allowed)
    end procedure check_estimate




    module procedure check_tensor
        integer :: i
        character(len=*), parameter :: UNAMES(8) = [character(len=11) :: 'u_mass', 'u_l', &
            'u_l_prime', 'u_b', 'u_b_prime', 'u_g', 'u_period', 'u_amplitude']
        character(len=*), parameter :: XNAMES(6) = [character(len=7) :: 'mass', 'l', &
            'l_prime', 'b', 'b_prime', 'g']
        real(dp) :: xv(6)
        if (stat%code /= STATUS_OK) return
        xv = [bod%mass, sus%l, sus%l_prime, sus%b, sus%b_prime, sus%g]
        do i = 1, size(self%u)
            call finite(stat, 'tensor', trim(UNAMES(i)), self%u(i))
            if (stat%code /= STATUS_OK) return
            if (self%u(i) < 0.0_dp .or. self%u(i) > DIM_MAX) call bad(stat, 'tensor', &
                trim(UNAMES(i)), rshort(self%u(i)), 'a standard uncertainty out of range', &
                '0 <= '//trim(UNAMES(i))//' <= '//rshort(DIM_MAX)//' (deck units; 0: not known)')
        end do
        if (stat%code /= STATUS_OK) return
        ! the 5-sigma range of each input inside its domain (check_measurement's rule); the
        ! periods and amplitudes are the table's, checked with it
        do i = 1, 6
            call in_domain(stat, 'tensor', trim(UNAMES(i)), self%u(i), trim(XNAMES(i)), &
                           xv(i), 0.0_dp, 0.0_dp)
        end do
        call finite(stat, 'tensor', 'u_direction', self%u_direction)
        if (stat%code /= STATUS_OK) return
        if (self%u_direction < 0.0_dp .or. self%u_direction > 30.0_dp) &
            call bad(stat, 'tensor', 'u_direction', rshort(self%u_direction), &
                     'a standard uncertainty of a direction out of range', '0 <= u_direction '// &
                     '<= 30 (degrees)')
        do i = 1, 3
            call finite(stat, 'tensor', 'cg', self%cg(i))
        end do
        if (stat%code /= STATUS_OK) return
        if (self%monte_carlo == 1 .or. self%monte_carlo < 0 .or. &
            self%monte_carlo > MAX_MONTE_CARLO) call bad(stat, 'tensor', 'monte_carlo', &
            itoa(self%monte_carlo), 'number of Monte Carlo samples out of range', &
            '0 (first order only) or 2 <= monte_carlo <= '//itoa(MAX_MONTE_CARLO))
        if (stat%code /= STATUS_OK) return
        if (self%plan /= 0 .and. (self%plan < 6 .or. self%plan > 26)) &
            call bad(stat, 'tensor', 'plan', itoa(self%plan), 'number of hangs to plan '// &
                     'out of range', '0 (no plan) or 6 <= plan <= 26 (the 13 face, edge and '// &
                     'corner axes of the body frame, a hang with up -u being the hang with up '// &
                     'u; past 13 some are timed twice)')
        if (stat%code /= STATUS_OK) return
        if (self%plan_add /= 0 .and. (self%plan_add < 1 .or. self%plan_add > 20)) &
            call bad(stat, 'tensor', 'plan_add', itoa(self%plan_add), 'number of hangs to '// &
                     'add out of range', '0 (none) or 1 <= plan_add <= 20 (hangs added to '// &
                     'the table of hangs)')
        if (stat%code /= STATUS_OK) return
        if (self%plan_add > 0 .and. (self%plan > 0 .or. len_trim(self%hangs) == 0)) &
            call bad(stat, 'tensor', 'plan_add', itoa(self%plan_add), 'hangs to add need a '// &
                     'table of hangs and no plan', 'plan_add with hangs = ''FILE'' (the hangs '// &
                     'timed so far), or plan = N alone (a whole plan)')
        if (stat%code /= STATUS_OK) return
        call check_fixture()
        if (stat%code /= STATUS_OK) return
        if (trim(self%estimate) /= 'tensor' .and. trim(self%estimate) /= 'tensor cg') &
            call bad(stat, 'tensor', 'estimate', quoted(trim(self%estimate)), 'not an '// &
                     'estimate of tensor', '''tensor'' (the six entries) or ''tensor cg'' '// &
                     '(and the mass centre in the body frame)')
        call finite(stat, 'tensor', 'u_attitude', self%u_attitude)
        if (stat%code /= STATUS_OK) return
        if (.not. (self%u_attitude > 0.0_dp .and. self%u_attitude <= 30.0_dp)) &
            call bad(stat, 'tensor', 'u_attitude', rshort(self%u_attitude), 'a standard '// &
                     'uncertainty of a hang''s attitude out of range', '0 < u_attitude <= 30 '// &
                     '(degrees)')
        if (stat%code /= STATUS_OK) return
        if (requested .and. len_trim(self%hangs) == 0 .and. &
            self%plan == 0) call bad(stat, 'tensor', 'hangs', '''''', 'no table of hangs', &
            'hangs = ''FILE'' (a table, relative to the deck''s folder), or plan = N to '// &
            'plan N hangs')
    contains
        !> The fixture: finite, its mass and u not negative, its inertia a symmetric matrix
        !! with a diagonal not negative, its frame 'body' or 'hang'.
        subroutine check_fixture()
            integer :: j, k
            call finite(stat, 'tensor', 'fixture_mass', self%fixture_mass)
            call finite(stat, 'tensor', 'u_fixture_mass', self%u_fixture_mass)
            do k = 1, 3
                call finite(stat, 'tensor', 'fixture_cg', self%fixture_cg(k))
                call finite(stat, 'tensor', 'u_fixture_cg', self%u_fixture_cg(k))
                do j = 1, 3
                    call finite(stat, 'tensor', 'fixture_inertia', self%fixture_inertia(j, k))
                    call finite(stat, 'tensor', 'u_fixture_inertia', &
                                self%u_fixture_inertia(j, k))
                end do
            end do
            if (stat%code /= STATUS_OK) return
            if (self%fixture_mass < 0.0_dp .or. self%fixture_mass > DIM_MAX) call bad(stat, &
                'tensor', 'fixture_mass', rshort(self%fixture_mass), 'a mass out of range', &
                '0 <= fixture_mass <= '//rshort(DIM_MAX)//' (deck units; 0: no fixture)')
            if (self%u_fixture_mass < 0.0_dp .or. any(self%u_fixture_cg < 0.0_dp) .or. &
                any(self%u_fixture_inertia < 0.0_dp)) call bad(stat, 'tensor', &
                'u_fixture_*', rshort(min(self%u_fixture_mass, minval(self%u_fixture_cg), &
                minval(self%u_fixture_inertia))), 'a negative standard uncertainty', &
                'u_fixture_mass, u_fixture_cg, u_fixture_inertia >= 0')
            if (stat%code /= STATUS_OK) return
            if (maxval(abs(self%fixture_inertia - transpose(self%fixture_inertia))) > &
                1.0e-9_dp*maxval(abs(self%fixture_inertia)) .or. &
                any([(self%fixture_inertia(k, k), k=1, 3)] < 0.0_dp)) call bad(stat, &
                'tensor', 'fixture_inertia', rlist_short(reshape(self%fixture_inertia, [9])), &
                'not an inertia tensor', 'a symmetric 3 x 3 matrix (fixture_inertia(1,:) '// &
                '= Jxx, Jxy, Jxz, ...; Jxy = -int x y dm) with its diagonal >= 0')
            if (stat%code /= STATUS_OK) return
            if (trim(self%fixture_frame) /= 'body' .and. trim(self%fixture_frame) /= 'hang') &
                call bad(stat, 'tensor', 'fixture_frame', quoted(trim(self%fixture_frame)), &
                         'not a frame of the fixture', '''body'' (it turns with the body: '// &
                         'the body frame of the table) or ''hang'' (it stays with the hang: '// &
                         'along CD, across, up from the midpoint of CD)')
        end subroutine check_fixture
    end procedure check_tensor

end submodule measure_checks
