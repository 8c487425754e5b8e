!> The hangs of an inertia-tensor measurement (analysis tensor): the table of hangs read and
!! checked into hang types, one hang per body orientation, one row per timing.
!!
!! The table (module tables: blanks, comma or semicolon separators, quotes, CR LF, a byte
!! order mark, a header naming the columns) has columns named from HANG_COLUMNS:
!!
!! * `hang`: rows with the same value are repeated timings of one hang (absent: each row is
!!   a hang of its own);
!! * `up_x, up_y, up_z`: the body-frame direction that points up at rest (any length but
!!   0), and `along_x, along_y, along_z`: the body-frame direction from the attachment point
!!   C toward D (orthogonalised against up);
!! * or instead `c_x, c_y, c_z, d_x, d_y, d_z`: the body-frame points C and D where the
!!   cables were attached, with the mass centre in the body frame from &tensor cg.  At rest
!!   the mass centre hangs in the vertical plane through CD, so C, D and the mass centre fix
!!   up (the normal to CD in that plane, away from the mass centre), along (D - C),
!!   b_prime (|D - C|), cg_depth and cg_offset;
!! * `period`: the total time of `cycles` cycles (default 1) in s; `amplitude`: the peak
!!   theta4 at which it was timed, degrees (default 0: small amplitude); `u_period`: the
!!   standard uncertainty of the period column's value (default &tensor u_period);
!! * any of `l, l_prime, b, b_prime, cg_depth, cg_offset`: the hang's own rig (a column
!!   absent takes the deck's value for every hang).
!!
!! In the model's terms (Kane & Tseng's ntilde frame of the hang): ntilde_1 = -up points
!! down at rest, ntilde_3 = -along points from D to C, ntilde_2 = ntilde_3 x ntilde_1.
!! Failures are ERR_DECK statuses of one line naming the table, its line or column, what
!! is wrong and what is allowed.  No routine stops.
module hang_table
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, rshort, rlist_short, quoted, next_word, commas, clip
    use rig_groups, only: suspension_group_t, body_group_t
    use measure_groups, only: tensor_group_t
    use tables, only: table_t, read_table
    implicit none
    private

    !> One hang: the body set in one orientation on one rig (deck units).
    type, public :: hang_t
        integer :: id = 0                       !! the table's `hang` value
        integer :: line = 0                     !! the line of its first row in the table
        real(dp) :: up(3) = [0.0_dp, 0.0_dp, 1.0_dp]    !! unit, body frame: up at rest
        real(dp) :: along(3) = [1.0_dp, 0.0_dp, 0.0_dp] !! unit, body frame, normal to up: C to D
        real(dp) :: l = 1.0_dp, l_prime = 1.0_dp, b = 1.0_dp, b_prime = 1.0_dp
        real(dp) :: cg_depth = 0.5_dp, cg_offset = 0.0_dp   !! the mass centre below CD, along CD
        !> l, l_prime, b, b_prime given by this hang's own columns (independent inputs of
        !! the hang), else the deck's (inputs common to every hang)
        logical :: own(4) = .false.
    end type hang_t

    !> One timing of a hang.
    type, public :: hang_row_t
        integer :: hang = 0                     !! index of its hang in hang_set_t%hangs
        integer :: line = 0                     !! its line in the table
        real(dp) :: period = 0.0_dp             !! the period, s (the column over cycles)
        real(dp) :: cycles = 1.0_dp             !! cycles timed
        real(dp) :: amplitude = 0.0_dp          !! peak theta4, degrees (0: small amplitude)
        real(dp) :: u_period = 0.0_dp           !! standard uncertainty of the period, s
    end type hang_row_t

    !> The hangs of a table and their timings.
    type, public :: hang_set_t
        type(hang_t), allocatable :: hangs(:)
        type(hang_row_t), allocatable :: rows(:)
        logical :: points = .false.             !! given as points C, D with &tensor cg
        logical :: own(4) = .false.             !! the table has columns l, l_prime, b, b_prime
    end type hang_set_t

    !> The column names a hangs table may use.
    character(len=*), parameter, public :: HANG_COLUMNS = 'hang up_x up_y up_z along_x '// &
        'along_y along_z period cycles amplitude u_period l l_prime b b_prime cg_depth '// &
        'cg_offset c_x c_y c_z d_x d_y d_z'
    !> The names of a hang's rig inputs in the order of hang_t%own.
    character(len=*), parameter, public :: RIG_NAMES(4) = [character(len=7) :: 'l', &
        'l_prime', 'b', 'b_prime']

    !> Most rows of a hangs table.
    integer, parameter, public :: MAX_HANG_ROWS = 10000
    !> Largest amplitude of a row (degrees; the period's own limit is the analysis's).
    real(dp), parameter :: AMPLITUDE_MAX = 90.0_dp
    !> along counts as parallel to up when its part normal to up is below this fraction.
    real(dp), parameter :: PARALLEL_TOL = 1.0e-6_dp
    !> Lengths of a hang over b_prime, and the body-frame points' size: as the deck's ratios.
    real(dp), parameter :: RATIO_MIN = 1.0e-3_dp, RATIO_MAX = 1.0e3_dp

    public :: read_hangs, hang_defaults, table_name

contains

    !> '&tensor hangs = 'FILE'': the head of every message about the table.
    function table_name(ten) result(s)
        type(tensor_group_t), intent(in) :: ten     !! the deck's &tensor
        character(len=:), allocatable :: s
        s = '&tensor hangs = '//quoted(trim(ten%hangs))
    end function table_name

    !> A hang with the deck's rig (l, l_prime, b, b_prime and the mass centre of &body:
    !! cg_depth, cg_offset, or r, lambda); have_cg = .false. when the deck gave no mass
    !! centre.
    pure subroutine hang_defaults(sus, bod, h, have_cg)
        type(suspension_group_t), intent(in) :: sus     !! the deck's, normalised
        type(body_group_t), intent(in) :: bod           !! the deck's, normalised
        type(hang_t), intent(out) :: h
        logical, intent(out) :: have_cg
        h%l = sus%l
        h%l_prime = sus%l_prime
        h%b = sus%b
        h%b_prime = sus%b_prime
        have_cg = bod%gave('cg_depth') .or. bod%gave('cg_offset') .or. &
                  (bod%gave('r') .and. bod%gave('lambda'))
        h%cg_depth = bod%r*sin(bod%lambda)
        h%cg_offset = bod%r*cos(bod%lambda) - 0.5_dp*sus%b_prime
    end subroutine hang_defaults

    !> Read the deck's table of hangs (&tensor hangs_path) and check it: the columns, each
    !! row's values, rows of one hang with one geometry.
    subroutine read_hangs(ten, sus, bod, set, stat)
        type(tensor_group_t), intent(in) :: ten         !! the deck's &tensor
        type(suspension_group_t), intent(in) :: sus     !! the rig's defaults (normalised)
        type(body_group_t), intent(in) :: bod
        type(hang_set_t), intent(out) :: set
        type(status_t), intent(out) :: stat     !! ERR_DECK naming the table and the line
        type(table_t) :: tab
        type(hang_t) :: h0, h
        character(len=:), allocatable :: head
        integer :: c_hang, c_up(3), c_al(3), c_c(3), c_d(3), c_per, c_cyc, c_amp, c_u
        integer :: c_rig(4), c_depth, c_off, i, k, n, nh, j
        logical :: have_cg, form_up, form_pts
        integer, allocatable :: ids(:)
        head = table_name(ten)//': '
        call read_table(ten%hangs_path, tab, stat, MAX_HANG_ROWS)
        if (stat%code /= STATUS_OK) then
            stat%msg = head//stat%msg
            return
        end if
        ! the columns: every name known, one form of the geometry, period present
        do k = 1, tab%ncol
            if (len(tab%names(k)%s) == 0) then
                call set_error(stat, ERR_DECK, head//'column '//itoa(k)//' has no name (the '// &
                    'table needs a header line naming its columns); allowed: '// &
                    commas(HANG_COLUMNS))
                return
            end if
            if (index(' '//HANG_COLUMNS//' ', ' '//tab%names(k)%s//' ') == 0) then
                call set_error(stat, ERR_DECK, head//'unknown column '// &
                    quoted(clip(tab%names(k)%s))// &
                    '; allowed: '//commas(HANG_COLUMNS))
                return
            end if
            do j = 1, k - 1
                if (tab%names(j)%s == tab%names(k)%s) then
                    call set_error(stat, ERR_DECK, head//'column '//quoted(tab%names(k)%s)// &
                        ' appears twice; allowed: each column once')
                    return
                end if
            end do
        end do
        c_hang = tab%column('hang')
        c_up = [tab%column('up_x'), tab%column('up_y'), tab%column('up_z')]
        c_al = [tab%column('along_x'), tab%column('along_y'), tab%column('along_z')]
        c_c = [tab%column('c_x'), tab%column('c_y'), tab%column('c_z')]
        c_d = [tab%column('d_x'), tab%column('d_y'), tab%column('d_z')]
        c_per = tab%column('period')
        c_cyc = tab%column('cycles')
        c_amp = tab%column('amplitude')
        c_u = tab%column('u_period')
        do k = 1, 4
            c_rig(k) = tab%column(trim(RIG_NAMES(k)))
        end do
        c_depth = tab%column('cg_depth')
        c_off = tab%column('cg_offset')
        form_up = any(c_up > 0) .or. any(c_al > 0)
        form_pts = any(c_c > 0) .or. any(c_d > 0)
        if (form_up .and. form_pts) then
            call set_error(stat, ERR_DECK, head//'both up/along and c/d columns; allowed: '// &
                'the orientation either as up_x, up_y, up_z, along_x, along_y, along_z or as '// &
                'the attachment points c_x, c_y, c_z, d_x, d_y, d_z, not both')
            return
        end if
        if (.not. (form_up .or. form_pts)) then
            call set_error(stat, ERR_DECK, head//'no column of the orientation; allowed: '// &
                'up_x, up_y, up_z, along_x, along_y, along_z (the body-frame directions up '// &
                'and from C toward D) or c_x, c_y, c_z, d_x, d_y, d_z (the attachment points)')
            return
        end if
        if (form_up) then
            call need3(c_up, 'up_x up_y up_z')
            call need3(c_al, 'along_x along_y along_z')
        else
            call need3(c_c, 'c_x c_y c_z')
            call need3(c_d, 'd_x d_y d_z')
            if (stat%code /= STATUS_OK) return
            if (.not. ten%cg_given) then
                call set_error(stat, ERR_DECK, head//'hangs given by the attachment points C '// &
                    'and D need the mass centre in the body frame; allowed: &tensor cg = x, '// &
                    'y, z with the c_x ... d_z columns')
                return
            end if
            if (c_rig(4) > 0 .or. c_depth > 0 .or. c_off > 0) then
                call set_error(stat, ERR_DECK, head//'column '//quoted(trim(merge('b_prime  ', &
                    'cg_depth ', c_rig(4) > 0)))//' with the attachment points; allowed: '// &
                    'b_prime, cg_depth and cg_offset follow from C, D and &tensor cg (give '// &
                    'them only with up/along)')
                return
            end if
        end if
        if (stat%code /= STATUS_OK) return
        if (c_per == 0) then
            call set_error(stat, ERR_DECK, head//'no column ''period''; allowed: a column '// &
                '''period'' (the time of ''cycles'' cycles, s)')
            return
        end if
        if (form_up .and. ten%cg_given) then
            call set_error(stat, ERR_DECK, '&tensor cg = '//rlist_short(ten%cg)// &
                ': the mass centre in the body frame is used with hangs given by their '// &
                'attachment points; allowed: cg with the c_x ... d_z columns, or cg_depth, '// &
                'cg_offset (&body or columns) with up/along')
            return
        end if
        call hang_defaults(sus, bod, h0, have_cg)
        ! without a mass centre in the deck, a cg_depth column with the offset 0 by default
        if (.not. have_cg) h0%cg_offset = 0.0_dp
        if (form_up .and. .not. have_cg .and. c_depth == 0) then
            call set_error(stat, ERR_DECK, 'not given: &body the mass centre (cg_depth and '// &
                'cg_offset, or r and lambda); a deck with analyses = ''tensor'' gives every '// &
                'physical input itself (the defaults are the paper''s dimensionless scene); '// &
                'allowed: &body cg_depth, cg_offset for every hang, or columns cg_depth (and '// &
                'cg_offset) in '//table_name(ten)//', or c_x ... d_z with &tensor cg')
            return
        end if
        ! the rows
        n = tab%nrow
        allocate (set%rows(n), set%hangs(n), ids(n))
        set%points = form_pts
        set%own = c_rig > 0
        if (form_pts) set%own(4) = .true.
        nh = 0
        do i = 1, n
            h = h0
            h%line = tab%line(i)
            h%id = i
            if (c_hang > 0) then
                if (abs(tab%v(i, c_hang)) > 1.0e9_dp .or. &
                    tab%v(i, c_hang) /= anint(tab%v(i, c_hang))) then
                    call row_error(i, 'hang = '//rshort(tab%v(i, c_hang))//' is not a whole '// &
                        'number; allowed: a whole number naming the hang, |hang| <= 1e9')
                    return
                end if
                h%id = nint(tab%v(i, c_hang))
            end if
            do k = 1, 4
                if (c_rig(k) > 0) then
                    call set_rig(h, k, tab%v(i, c_rig(k)))
                    h%own(k) = .true.
                end if
            end do
            if (c_depth > 0) h%cg_depth = tab%v(i, c_depth)
            if (c_off > 0) h%cg_offset = tab%v(i, c_off)
            if (form_up) then
                call orientation(i, tab%v(i, c_up), tab%v(i, c_al), h)
            else
                call from_points(i, tab%v(i, c_c), tab%v(i, c_d), ten%cg, h)
            end if
            if (stat%code /= STATUS_OK) return
            call check_rig(i, h)
            if (stat%code /= STATUS_OK) return
            ! the timing
            set%rows(i)%line = tab%line(i)
            set%rows(i)%cycles = 1.0_dp
            if (c_cyc > 0) set%rows(i)%cycles = tab%v(i, c_cyc)
            if (.not. (set%rows(i)%cycles >= 1.0_dp .and. set%rows(i)%cycles <= 1.0e6_dp)) then
                call row_error(i, 'cycles = '//rshort(set%rows(i)%cycles)//' out of range; '// &
                    'allowed: 1 <= cycles <= 1e6 (cycles timed by the period column)')
                return
            end if
            if (.not. (tab%v(i, c_per) > 0.0_dp .and. tab%v(i, c_per) < 1.0e9_dp)) then
                call row_error(i, 'period = '//rshort(tab%v(i, c_per))//' out of range; '// &
                    'allowed: 0 < period < 1e9 (s, the time of cycles cycles)')
                return
            end if
            set%rows(i)%period = tab%v(i, c_per)/set%rows(i)%cycles
            if (c_amp > 0) set%rows(i)%amplitude = tab%v(i, c_amp)
            if (.not. (set%rows(i)%amplitude >= 0.0_dp .and. &
                       set%rows(i)%amplitude < AMPLITUDE_MAX)) then
                call row_error(i, 'amplitude = '//rshort(set%rows(i)%amplitude)//' out of '// &
                    'range; allowed: 0 <= amplitude < '//rshort(AMPLITUDE_MAX)//' (degrees '// &
                    'of theta4; 0: small amplitude)')
                return
            end if
            set%rows(i)%u_period = ten%u(7)
            if (c_u > 0) set%rows(i)%u_period = tab%v(i, c_u)
            if (.not. (set%rows(i)%u_period >= 0.0_dp .and. &
                       set%rows(i)%u_period < tab%v(i, c_per))) then
                call row_error(i, 'u_period = '//rshort(set%rows(i)%u_period)//' out of '// &
                    'range; allowed: 0 <= u_period < period (s, of the period column)')
                return
            end if
            set%rows(i)%u_period = set%rows(i)%u_period/set%rows(i)%cycles
            ! the hang: a new one, or the same geometry as its earlier rows
            k = 0
            if (nh > 0) k = findloc(ids(1:nh), h%id, 1)
            if (k == 0) then
                nh = nh + 1
                ids(nh) = h%id
                set%hangs(nh) = h
                k = nh
            else if (.not. same_hang(set%hangs(k), h)) then
                call row_error(i, 'hang '//itoa(h%id)//' has another orientation or rig '// &
                    'than on line '//itoa(set%hangs(k)%line)//'; allowed: rows of one hang '// &
                    'repeat its timing with the same up, along (or c, d) and rig columns')
                return
            end if
            set%rows(i)%hang = k
        end do
        set%hangs = set%hangs(1:nh)

    contains

        !> All three columns of a vector, or a message naming the missing ones.
        subroutine need3(cols, names)
            integer, intent(in) :: cols(3)
            character(len=*), intent(in) :: names
            integer :: m, i1, i2
            if (stat%code /= STATUS_OK .or. all(cols > 0)) return
            i2 = 0
            do m = 1, 3
                call next_word(names, i2, i1)
                if (cols(m) == 0) exit
            end do
            call set_error(stat, ERR_DECK, head//'no column '//quoted(names(i1:i2))//' (the '// &
                'table gives '//given(cols, names)//'); allowed: all of '//commas(names))
        end subroutine need3

        function given(cols, names) result(s)
            integer, intent(in) :: cols(3)
            character(len=*), intent(in) :: names
            character(len=:), allocatable :: s
            integer :: m, i1, i2
            s = ''
            i2 = 0
            do m = 1, 3
                call next_word(names, i2, i1)
                if (cols(m) > 0) then
                    if (len(s) > 0) s = s//', '
                    s = s//names(i1:i2)
                end if
            end do
        end function given

        subroutine row_error(i, what)
            integer, intent(in) :: i
            character(len=*), intent(in) :: what
            call set_error(stat, ERR_DECK, head//'line '//itoa(tab%line(i))//': '//what)
        end subroutine row_error

        subroutine set_rig(hh, k, v)
            type(hang_t), intent(inout) :: hh
            integer, intent(in) :: k
            real(dp), intent(in) :: v
            select case (k)
            case (1)
                hh%l = v
            case (2)
                hh%l_prime = v
            case (3)
                hh%b = v
            case default
                hh%b_prime = v
            end select
        end subroutine set_rig

        !> up and along of a row: up not 0, along not parallel to it.
        subroutine orientation(i, up, along, hh)
            integer, intent(in) :: i
            real(dp), intent(in) :: up(3), along(3)
            type(hang_t), intent(inout) :: hh
            real(dp) :: nu, a(3), na
            nu = norm2(up)
            if (.not. (nu > 1.0e-300_dp)) then
                call row_error(i, 'up = '//rlist_short(up)//' is the zero vector; allowed: '// &
                    'the body-frame direction that points up at rest (any length but 0)')
                return
            end if
            hh%up = up/nu
            a = along - dot_product(along, hh%up)*hh%up
            na = norm2(a)
            if (.not. (na > PARALLEL_TOL*norm2(along)) .or. .not. (na > 0.0_dp)) then
                call row_error(i, 'along = '//rlist_short(along)//' is 0 or parallel to up = '// &
                    rlist_short(up)//'; allowed: the body-frame direction from C toward D, '// &
                    'not along up')
                return
            end if
            hh%along = a/na
        end subroutine orientation

        !> up, along, b_prime, cg_depth, cg_offset from the points C, D and the mass centre.
        subroutine from_points(i, c, dd, cg, hh)
            integer, intent(in) :: i
            real(dp), intent(in) :: c(3), dd(3), cg(3)
            type(hang_t), intent(inout) :: hh
            real(dp) :: a(3), bp, s, p(3), depth
            a = dd - c
            bp = norm2(a)
            if (.not. (bp > 1.0e-12_dp*max(norm2(c), norm2(dd), norm2(cg)))) then
                call row_error(i, 'D = '//rlist_short(dd)//' is C = '//rlist_short(c)// &
                    '; allowed: two distinct attachment points')
                return
            end if
            hh%along = a/bp
            s = dot_product(cg - c, hh%along)
            p = (cg - c) - s*hh%along
            depth = norm2(p)
            if (.not. (depth > 1.0e-6_dp*bp)) then
                call row_error(i, '&tensor cg = '//rlist_short(cg)//' lies on the line CD; '// &
                    'allowed: a mass centre off the line through the attachment points (it '// &
                    'hangs below it)')
                return
            end if
            hh%up = -p/depth
            hh%b_prime = bp
            hh%own(4) = .true.          ! the spacing of this hang's own attachment points
            hh%cg_depth = depth
            hh%cg_offset = s - 0.5_dp*bp
        end subroutine from_points

        !> A hang's rig in range: lengths > 0 over b_prime in RATIO_MIN .. RATIO_MAX, the
        !! mass centre below CD.
        subroutine check_rig(i, hh)
            integer, intent(in) :: i
            type(hang_t), intent(in) :: hh
            real(dp) :: v(4)
            integer :: m
            v = [hh%l, hh%l_prime, hh%b, hh%b_prime]
            do m = 1, 4
                if (.not. (v(m) > 0.0_dp .and. v(m) < 1.0e100_dp)) then
                    call row_error(i, trim(RIG_NAMES(m))//' = '//rshort(v(m))//' out of '// &
                        'range; allowed: 0 < '//trim(RIG_NAMES(m))//' < 1e100 (deck units)')
                    return
                end if
            end do
            do m = 1, 3
                if (.not. (v(m)/v(4) >= RATIO_MIN .and. v(m)/v(4) <= RATIO_MAX)) then
                    call row_error(i, trim(RIG_NAMES(m))//'/b_prime = '//rshort(v(m)/v(4))// &
                        ' out of range; allowed: '//rshort(RATIO_MIN)//' <= '// &
                        trim(RIG_NAMES(m))//'/b_prime <= '//rshort(RATIO_MAX))
                    return
                end if
            end do
            if (.not. (hh%cg_depth > 1.0e-6_dp*hh%b_prime .and. &
                       hh%cg_depth <= RATIO_MAX*hh%b_prime)) then
                call row_error(i, 'cg_depth = '//rshort(hh%cg_depth)//': the mass centre '// &
                    'must hang below the line CD; allowed: 1e-6 b_prime < cg_depth <= '// &
                    rshort(RATIO_MAX)//' b_prime')
                return
            end if
            if (.not. (abs(hh%cg_offset) <= RATIO_MAX*hh%b_prime)) then
                call row_error(i, 'cg_offset = '//rshort(hh%cg_offset)//' out of range; '// &
                    'allowed: |cg_offset| <= '//rshort(RATIO_MAX)//' b_prime')
                return
            end if
        end subroutine check_rig

    end subroutine read_hangs

    !> Two rows describe one hang: the same orientation and rig (to roundoff).
    pure logical function same_hang(a, b)
        type(hang_t), intent(in) :: a, b
        real(dp), parameter :: TOL = 1.0e-12_dp
        same_hang = all(abs(a%up - b%up) <= TOL) .and. all(abs(a%along - b%along) <= TOL) &
            .and. near(a%l, b%l) .and. near(a%l_prime, b%l_prime) .and. near(a%b, b%b) .and. &
            near(a%b_prime, b%b_prime) .and. abs(a%cg_depth - b%cg_depth) <= TOL*a%b_prime &
            .and. abs(a%cg_offset - b%cg_offset) <= TOL*a%b_prime
    contains
        pure logical function near(x, y)
            real(dp), intent(in) :: x, y
            near = abs(x - y) <= TOL*abs(x)
        end function near
    end function same_hang

end module hang_table
