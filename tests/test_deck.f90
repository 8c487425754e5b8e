!> Tests of the deck reader (every value read back, every bad input an ERR_DECK naming the
!! variable) and of the atomic output files.
module test_deck
    use, intrinsic :: ieee_arithmetic, only: ieee_usual
    use kinds, only: dp
    use status, only: status_t, STATUS_OK, ERR_DECK, ERR_IO
    use testing, only: tester_t, write_text, exists, shell_count, msg_of, scratch_dir
    use deck, only: deck_t, read_deck, analysis_requested, deck_echo
    use fptraps, only: traps_off, traps_restore
    use output_io, only: atomic_open, atomic_commit, atomic_abort, write_kv, all_finite, &
                         out_files_t, make_dir, process_id
    use text, only: itoa, rshort
    use driver, only: error_line
    use unused_arg, only: unused
    implicit none
    private

    public :: run_deck_tests

    character(len=*), parameter :: SCRATCH = 'build/test_decks'
    character, parameter :: NL = new_line('a')

    ! the groups of a complete, valid deck (the triangular plate of input/)
    character(len=*), parameter :: G_SCENE = &
        "&scene title = 'Plate, l = l'' = 2b', analyses = 'simulate  Floquet chart' /"
    character(len=*), parameter :: G_SUSP = &
        '&suspension b = 1.5, b_prime = 1.25, l = 2.5, l_prime = 1.75, g = 9.81 /'
    character(len=*), parameter :: G_BODY = &
        '&body mass = 2.0, inertia = 0.0625, 0.1875, 0.25,'//NL// &
        '      r = 0.5, lambda = 0.25,   ! a comment inside a group'//NL// &
        '      btilde(1,:) = -0.7071067811865476, 0.0, -0.7071067811865476,'//NL// &
        '      btilde(2,:) = -0.7071067811865476, 0.0,  0.7071067811865476,'//NL// &
        '      btilde(3,:) = 0.0, 1.0, 0.0,'//NL// &
        '      sway_depth = 0.75 /'
    character(len=*), parameter :: G_START = &
        "&start mode = 'Angles', amplitude = 30.0, tilt = 0.1, theta = 0.1, 0.2, 0.3, 0.4," &
        //NL//"       theta_dot = -1, -2, -3, -4 /"
    character(len=*), parameter :: G_INTEG = &
        '&integration tau_end = 10.0, dtau_out = 0.5, rtol = 1e-9, atol = 1d-11, ' // &
        'error_estimate = .true., sensitivity_error_control = .true. /'
    ! minimal required groups
    character(len=*), parameter :: MIN_SUSP = '&suspension b = 1.0, l = 2.0 /'
    character(len=*), parameter :: MIN_BODY = '&body mass = 1.0 /'
    ! the optional analysis groups
    character(len=*), parameter :: G_FLOQUET = &
        '&floquet amplitude = 30.0, segments = 8, rtol = 1e-9 /'
    character(len=*), parameter :: G_CHART = &
        "&chart x = 'Lambda', x_min = -1.0, x_max = 1.25, nx = 50,"//NL// &
        "       y = 'INERTIA_RATIO', y_min = 0.5, y_max = 2.0, ny = 60 /  ! a comment"

contains

    subroutine run_deck_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        character(len=*), parameter :: dir = SCRATCH    !! directory for deck files
        call unused(exe)   ! every suite is given the executable; this one needs none
        call scratch_dir(dir)
        if (t%want('deck: a complete deck reads back')) call test_complete(t, dir)
        if (t%want('deck: defaults for absent groups')) call test_defaults(t, dir)
        if (t%want('deck: bad input is ERR_DECK naming the variable')) call test_bad(t, dir)
        if (t%want('deck: limits (subscripts, sizes, ratios, angles, rates, rows)')) &
            call test_limits(t, dir)
        if (t%want('deck: echo and key = value lines')) call test_echo(t, dir)
        if (t%want('deck: shortest reals of the echo')) call test_rshort(t)
        if (t%want('deck: atomic output files')) call test_atomic(t, dir)
        if (t%want('deck: the files of a run, committed or removed together')) &
            call test_run_files(t, dir)
        if (t%want('deck: &floquet and &chart')) call test_floquet_chart(t, dir)
        if (t%want('deck: model and &cables')) call test_cables(t, dir)
    end subroutine run_deck_tests

    ! ---------------------------------------------------------------------------------------
    subroutine test_complete(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        type(deck_t) :: d
        type(status_t) :: stat
        character(len=:), allocatable :: path
        real(dp), parameter :: s = 0.7071067811865476_dp
        path = dir//'/complete.nml'
        call write_text(path, '! a complete deck'//NL//G_SCENE//NL//G_SUSP//NL//G_BODY//NL// &
                        G_START//NL//G_INTEG//NL)
        call read_deck(path, d, stat)
        call t%check('complete: status ok ('//msg_of(stat)//')', stat%code == STATUS_OK)
        if (stat%code /= STATUS_OK) return
        call t%check('complete: path', d%path == path)
        call t%check('complete: name', d%name == 'complete')
        call t%check('complete: title', trim(d%scene%title) == 'Plate, l = l'' = 2b')
        call t%check('complete: model default', trim(d%scene%model) == 'kane')
        call t%check('complete: simulate requested', analysis_requested(d, 'simulate'))
        call t%check('complete: floquet requested (case)', analysis_requested(d, 'floquet'))
        call t%check('complete: chart requested', analysis_requested(d, 'chart'))
        call t%check('complete: work_precision not requested', &
                     .not. analysis_requested(d, 'work_precision'))
        call t%check('complete: partial word not requested', .not. analysis_requested(d, 'sim'))
        call t%check_close('complete: b', d%suspension%b, 1.5_dp)
        call t%check_close('complete: b_prime', d%suspension%b_prime, 1.25_dp)
        call t%check_close('complete: l', d%suspension%l, 2.5_dp)
        call t%check_close('complete: l_prime', d%suspension%l_prime, 1.75_dp)
        call t%check_close('complete: g', d%suspension%g, 9.81_dp)
        call t%check_close('complete: mass', d%body%mass, 2.0_dp)
        call t%check('complete: inertia', all(d%body%inertia == [0.0625_dp, 0.1875_dp, 0.25_dp]))
        call t%check_close('complete: r', d%body%r, 0.5_dp)
        call t%check_close('complete: lambda', d%body%lambda, 0.25_dp)
        call t%check('complete: btilde row 1', all(d%body%btilde(1, :) == [-s, 0.0_dp, -s]))
        call t%check('complete: btilde row 2', all(d%body%btilde(2, :) == [-s, 0.0_dp, s]))
        call t%check('complete: btilde row 3', all(d%body%btilde(3, :) == [0.0_dp, 1.0_dp, 0.0_dp]))
        call t%check_close('complete: sway_depth', d%body%sway_depth, 0.75_dp)
        call t%check('complete: mode lower case', trim(d%start%mode) == 'angles')
        call t%check_close('complete: amplitude', d%start%amplitude, 30.0_dp)
        call t%check_close('complete: tilt', d%start%tilt, 0.1_dp)
        call t%check('complete: theta', all(d%start%theta == [0.1_dp, 0.2_dp, 0.3_dp, 0.4_dp]))
        call t%check('complete: theta_dot', all(d%start%theta_dot == [-1.0_dp, -2.0_dp, -3.0_dp, &
                                                                -4.0_dp]))
        call t%check_close('complete: tau_end', d%integration%tau_end, 10.0_dp)
        call t%check_close('complete: dtau_out', d%integration%dtau_out, 0.5_dp)
        call t%check_close('complete: rtol', d%integration%rtol, 1.0e-9_dp)
        call t%check_close('complete: atol', d%integration%atol, 1.0e-11_dp)
        call t%check('complete: error_estimate', d%integration%error_estimate)
        call t%check('complete: sensitivity_error_control', d%integration%sensitivity_error_control)

        ! the decks shipped in input/ are valid
        call read_deck('input/cylinder_l180.nml', d, stat)
        call t%check('input/cylinder_l180.nml reads ('//msg_of(stat)//')', &
                     stat%code == STATUS_OK)
        call t%check('input/cylinder_l180.nml: name', d%name == 'cylinder_l180')
        call t%check_close('input/cylinder_l180.nml: l_prime', d%suspension%l_prime, 1.8_dp)
        call read_deck('input/triangle_plate.nml', d, stat)
        call t%check('input/triangle_plate.nml reads ('//msg_of(stat)//')', &
                     stat%code == STATUS_OK)
        call t%check('input/triangle_plate.nml: btilde(3,:)', &
                     all(d%body%btilde(3, :) == [0.0_dp, 1.0_dp, 0.0_dp]))
    end subroutine test_complete

    subroutine test_defaults(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        type(deck_t) :: d, ref
        type(status_t) :: stat
        call write_text(dir//'/minimal', MIN_SUSP//NL//MIN_BODY//NL)
        call read_deck(dir//'/minimal', d, stat)
        call t%check('defaults: status ok ('//msg_of(stat)//')', stat%code == STATUS_OK)
        if (stat%code /= STATUS_OK) return
        call t%check('defaults: name without .nml', d%name == 'minimal')
        call t%check('defaults: analyses', analysis_requested(d, 'simulate') .and. &
                     .not. analysis_requested(d, 'floquet'))
        call t%check('defaults: title', len_trim(d%scene%title) == 0)
        call t%check('defaults: mode', trim(d%start%mode) == 'raised')
        call t%check('defaults: l_prime', d%suspension%l_prime == ref%suspension%l_prime)
        call t%check('defaults: inertia', all(d%body%inertia == ref%body%inertia))
        call t%check('defaults: btilde identity', all(d%body%btilde == reshape([1.0_dp, 0.0_dp, &
                     0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 3])))
        call t%check('defaults: amplitude', d%start%amplitude == 45.0_dp)
        call t%check('defaults: integration', d%integration%tau_end == 60.0_dp .and. &
                     d%integration%dtau_out == 0.05_dp .and. &
                     d%integration%rtol == 1.0e-10_dp .and. d%integration%atol == 1.0e-12_dp &
                     .and. .not. d%integration%error_estimate)
        ! a second read into the same variable starts from the defaults again
        call write_text(dir//'/minimal2.nml', '&suspension l = 3.0 /'//NL// &
                        '&body mass = 1.0 /'//NL)
        call read_deck(dir//'/minimal2.nml', d, stat)
        call t%check('defaults: reread ok', stat%code == STATUS_OK)
        call t%check('defaults: reread b', d%suspension%b == 1.0_dp .and. d%suspension%l == 3.0_dp)
        call t%check('defaults: name strips directory', d%name == 'minimal2')
        ! values at the limits are valid and do not overflow inside the checks
        call write_text(dir//'/huge.nml', MIN_SUSP//NL// &
                        '&body inertia = 1e6, 1e6, 1e-6 /'//NL// &
                        '&integration tau_end = 1e6, dtau_out = 10 /'//NL)
        call read_deck(dir//'/huge.nml', d, stat)
        call t%check('defaults: huge valid values ok ('//msg_of(stat)//')', &
                     stat%code == STATUS_OK)
        ! no newline after the last group
        call write_text(dir//'/no_newline.nml', MIN_SUSP//NL//'&body mass = 3.0 /')
        call read_deck(dir//'/no_newline.nml', d, stat)
        call t%check('defaults: last line without newline ('//msg_of(stat)//')', &
                     stat%code == STATUS_OK .and. d%body%mass == 3.0_dp)
    end subroutine test_defaults

    ! ---------------------------------------------------------------------------------------
    !> The limits: subscripts the run-time library cannot be trusted with, deck
    !! size and line length, a device as a deck, the dimensional range and the scale-free
    !! ratios, angles (bounded, then reduced modulo 2 pi), rates, tau_end and the row limit;
    !! each a one-line ERR_DECK naming the variable and what is allowed.
    subroutine test_limits(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        type(deck_t) :: d
        type(status_t) :: stat
        character(len=*), parameter :: SB = MIN_SUSP//NL//MIN_BODY//NL
        integer, parameter :: qp = selected_real_kind(30)
        real(qp), parameter :: TWO_PI_Q = 6.28318530717958647692528676655900577_qp
        real(dp) :: x(4), r
        integer :: k
        character(len=:), allocatable :: text

        ! gfortran 12 takes SIGSEGV on these (a subscript left open at the end of a line)
        call bad('open_subscript', '&suspension /'//NL//'&body inertia('//NL//'/', &
                 ['&body    ', 'inertia( ', 'one line '])
        call bad('open_subscript_comma', '&suspension /'//NL//'&body btilde(1,'//NL//'/', &
                 ['btilde(1,', 'one line '])
        call bad('paren_in_value', '&suspension /'//NL//'&body inertia = ('//NL//'/', &
                 ['unexpected ''(''', 'inertia = (   '])
        call bad('bad_subscript', '&suspension /'//NL//'&body inertia(x) = 1 /', &
                 ['inertia(x)', 'integers  '])
        call good('subscript_on_its_line', '&suspension /'//NL//'&body inertia(1) = 0.125,'// &
                  NL//'btilde(1,:) = 1, 0, 0 /')
        ! sizes: a long line, a large deck, a device without newlines
        call bad('long_line', "&scene title = '"//repeat('x', 100000)//"' /"//NL//SB, &
                 ['line 1', '4096  '])
        text = repeat('! '//repeat('comment ', 7)//NL, 17000)
        call bad('large_deck', SB//text, ['1000000 bytes'])
        call read_deck('/dev/zero', d, stat)
        call t%check('limits: /dev/zero as a deck is ERR_DECK at once ('//msg_of(stat)//')', &
                     stat%code == ERR_DECK .and. index(msg_of(stat), 'longer than') > 0)
        ! the dimensional range
        call bad('b_prime_huge', '&suspension b_prime = 1e300 /'//NL//MIN_BODY, &
                 ['b_prime = 1e300', '1e-100         ', '1e100          '])
        call bad('b_prime_denormal', '&suspension b_prime = 4.9e-324 /'//NL//MIN_BODY, &
                 ['b_prime', '1e-100 '])
        call bad('inertia_denormal', MIN_SUSP//NL//'&body inertia = 1e-320, 0.1, 0.1 /', &
                 ['inertia', '1e-100 '])
        ! the scale-free ratios
        call bad('l_over_b_prime', '&suspension l = 1e4 /'//NL//MIN_BODY, &
                 ['l = 10000   ', 'l/b_prime   ', '<= 1000     '])
        call bad('b_tiny', '&suspension b = 1e-300 /'//NL//MIN_BODY, &
                 ['b = 1e-300', '1e-100    '])
        call bad('b_over_b_prime', '&suspension b = 1e-4 /'//NL//MIN_BODY, &
                 ['b = 0.0001           ', '0.001 <= b/b_prime   '])
        call bad('r_over_b_prime', MIN_SUSP//NL//'&body r = 1e300 /', ['r = 1e300', 'r/b_prime'])
        call bad('sway_depth', MIN_SUSP//NL//'&body sway_depth = -1e300 /', &
                 ['sway_depth = -1e300 ', '|sway_depth|/b_prime'])
        call bad('inertia_ratio', MIN_SUSP//NL//'&body mass = 1e-90 /', &
                 ['I1/(mass b_prime^2)       ', '<= 1000000 for each       '])
        call bad('inertia_small', MIN_SUSP//NL//'&body inertia = 1e-7, 0.1, 0.1 /', &
                 ['I1/(mass b_prime^2) = 1.000E-07'])
        call good('ratios_at_limits', '&suspension b = 0.001, l = 1000, l_prime = 999 /'//NL// &
                  '&body inertia = 1e-6, 1, 1, r = 1000, sway_depth = -1000 /')
        ! angles and rates
        call bad('tilt_huge', SB//'&start tilt = -1e10 /', ['tilt = -10000000000', &
                 'modulo 2 pi        '])
        call bad('theta_dot_huge', SB//"&start mode = 'angles', theta_dot = 0, 0, 0, 1e308 /", &
                 ['theta_dot', '1000     '])
        call bad('lambda_huge', MIN_SUSP//NL//'&body lambda = 1e7 /', ['lambda'])
        call write_text(dir//'/angles.nml', SB//"&start mode = 'angles', tilt = 7, "// &
                        'theta = -4, 0.5, 10, 1e5 /'//NL)
        call read_deck(dir//'/angles.nml', d, stat)
        call t%check('limits: angles read ('//msg_of(stat)//')', stat%code == STATUS_OK)
        x = [-4.0_dp, 0.5_dp, 10.0_dp, 1.0e5_dp]
        do k = 1, 4
            r = real(x(k) - TWO_PI_Q*anint(real(x(k), qp)/TWO_PI_Q), dp)
            call t%check_close('limits: theta('//itoa(k)//') reduced modulo 2 pi (quad '// &
                               'precision reference)', d%start%theta(k), r, atol=1.0e-15_dp)
        end do
        call t%check_close('limits: tilt reduced modulo 2 pi', d%start%tilt, &
                           real(7.0_qp - TWO_PI_Q, dp), atol=1.0e-15_dp)
        ! tau_end and the row limit
        call bad('tau_end_huge', SB//'&integration tau_end = 1e7, dtau_out = 1000 /', &
                 ['tau_end = 10000000', '1000000           '])
        call bad('rows', SB//'&integration tau_end = 60, dtau_out = 6e-6 /', &
                 ['dtau_out = 6e-6', 'row limit      ', '100000         '])

    contains

        subroutine good(label, deck_text)
            character(len=*), intent(in) :: label, deck_text
            call write_text(dir//'/good_'//label//'.nml', deck_text//NL)
            call read_deck(dir//'/good_'//label//'.nml', d, stat)
            call t%check('limits: '//label//' is valid ('//msg_of(stat)//')', &
                         stat%code == STATUS_OK)
        end subroutine good

        subroutine bad(label, deck_text, words)
            character(len=*), intent(in) :: label, deck_text
            character(len=*), intent(in) :: words(:)
            integer :: i
            character(len=:), allocatable :: path, m
            path = dir//'/limit_'//label//'.nml'
            call write_text(path, deck_text)
            call read_deck(path, d, stat)
            m = msg_of(stat)
            if (len(m) > 300) m = m(1:300)//'...'
            call t%check('limits: '//label//' is ERR_DECK ('//m//')', stat%code == ERR_DECK)
            call t%check('limits: '//label//' message is one line of at most 400 characters', &
                         len(msg_of(stat)) <= 400 .and. index(msg_of(stat), NL) == 0)
            do i = 1, size(words)
                call t%check('limits: '//label//' message contains "'//trim(words(i))//'" ('// &
                             m//')', index(msg_of(stat), trim(words(i))) > 0)
            end do
        end subroutine bad

    end subroutine test_limits

    ! ---------------------------------------------------------------------------------------
    subroutine test_bad(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        type(deck_t) :: d
        type(status_t) :: stat
        character(len=*), parameter :: SB = MIN_SUSP//NL//MIN_BODY//NL

        call read_deck(dir//'/no_such_deck.nml', d, stat)
        call t%check('bad: missing file is ERR_DECK', stat%code == ERR_DECK)
        call t%check('bad: missing file named ('//msg_of(stat)//')', &
                     index(msg_of(stat), dir//'/no_such_deck.nml') > 0)

        call bad('misspelled', '&suspension b = 1.0, lenght = 2 /'//NL//MIN_BODY, &
                 ['lenght     ', '&suspension', 'b_prime    '])
        call bad('non_numeric', '&suspension b = 1.0, l = abc /'//NL//MIN_BODY, &
                 ['l = abc    ', 'not a real '])
        call bad('non_numeric_2', MIN_SUSP//NL//'&body mass = 1.0.0 /', &
                 ['mass = 1.0.0'])
        call bad('repeated_point', MIN_SUSP//NL//'&body inertia = 1, 1, 1, 2 /', &
                 ['inertia   ', 'too many  '])
        call bad('nan', '&suspension b = NaN, l = 2.0 /'//NL//MIN_BODY, &
                 ['b = NaN   ', 'finite    '])
        call bad('inf', '&suspension l = Inf /'//NL//MIN_BODY, ['l = Inf'])
        call bad('overflow', SB//'&integration tau_end = 1e400 /', ['tau_end'])
        call bad('zero_length', '&suspension b_prime = 0.0 /'//NL//MIN_BODY, &
                 ['b_prime = 0', '> 0        '])
        call bad('negative_length', '&suspension l = -0.3 /'//NL//MIN_BODY, ['l = -0.3'])
        call bad('l_prime_zero', '&suspension l_prime = 0 /'//NL//MIN_BODY, ['l_prime = 0'])
        call bad('l_prime_negative', '&suspension l_prime = -1 /'//NL//MIN_BODY, &
                 ['l_prime = -1'])
        call bad('g_zero', '&suspension g = 0 /'//NL//MIN_BODY, ['g = 0'])
        call bad('mass_negative', MIN_SUSP//NL//'&body mass = -1 /', ['mass = -1'])
        call bad('inertia_zero', MIN_SUSP//NL//'&body inertia = 0.0, 1.0, 1.0 /', ['inertia'])
        call bad('btilde_not_unit', MIN_SUSP//NL//'&body btilde(1,:) = 1, 1, 0 /', &
                 ['btilde    ', 'row 1     ', 'orthonorm '])
        call bad('btilde_not_orthogonal', MIN_SUSP//NL//'&body btilde(2,:) = 0.6, 0.8, 0.0 /', &
                 ['btilde      ', 'orthogonal  ', 'rows 1 and 2'])
        call bad('btilde_left_handed', MIN_SUSP//NL//'&body btilde(3,:) = 0, 0, -1 /', &
                 ['btilde     ', 'left-handed', 'det        '])
        call bad('btilde_huge', MIN_SUSP//NL//'&body btilde(1,:) = 1e300, 0, 0 /', &
                 ['btilde = [1e300, 0, 0;'])
        call bad('triangle_I1', MIN_SUSP//NL//'&body inertia = 1.0, 0.2, 0.3 /', &
                 ['inertia             ', 'I1 > I2 + I3        ', 'triangle inequality '])
        call bad('triangle_I3', MIN_SUSP//NL//'&body inertia = 1e5, 1e5, 2.5e5 /', &
                 ['inertia = 100000, 100000, 250000', 'I3 > I1 + I2                    '])
        call bad('r_negative', MIN_SUSP//NL//'&body r = -0.1 /', ['r = -0.1'])
        call bad('missing_body', MIN_SUSP//NL, ['&body   ', 'required'])
        call bad('missing_suspension', MIN_BODY//NL, ['&suspension', 'required   '])
        call bad('truncated', MIN_SUSP//NL//'&body mass = 1.0, inertia = 0.1, 0.1, 0.1', &
                 ['&body    ', 'truncated'])
        call bad('unterminated', MIN_SUSP//NL//'&body mass = 1.0'//NL//'&start tilt = 0.1 /', &
                 ['&body          ', 'closing        ', 'before ''&start'''])
        call bad('empty', '', ['empty'])
        call bad('unknown_group', SB//'&intergation tau_end = 1 /', &
                 ['&intergation', 'allowed     '])
        call bad('unknown_analysis', "&scene analyses = 'simulate flocket' /"//NL//SB, &
                 ['analyses', 'flocket ', 'floquet '])
        call bad('empty_analyses', "&scene analyses = '' /"//NL//SB, ['analyses', 'simulate'])
        call bad('bad_model', "&scene model = 'euler' /"//NL//SB, ['model', 'kane '])
        call bad('bad_mode', "&start mode = 'dropped' /"//NL//SB, ['mode  ', 'raised', 'angles'])
        call bad('unquoted_mode', "&start mode = raised /"//NL//SB, ['mode  ', 'quoted'])
        call bad('amplitude_180', '&start amplitude = 180 /'//NL//SB, ['amplitude', '180      '])
        call bad('amplitude_zero', '&start amplitude = 0 /'//NL//SB, ['amplitude = 0'])
        call bad('theta_nan', "&start mode = 'angles', theta = 0, nan /"//NL//SB, ['theta'])
        call bad('dtau_out_gt_tau_end', SB//'&integration tau_end = 1, dtau_out = 2 /', &
                 ['dtau_out', 'tau_end '])
        call bad('too_many_rows', SB//'&integration tau_end = 1e6, dtau_out = 1e-3 /', &
                 ['dtau_out', '100000  '])
        call bad('rtol_zero', SB//'&integration rtol = 0 /', ['rtol ', '1e-14'])
        call bad('rtol_small', SB//'&integration rtol = 1e-15 /', ['rtol = 1e-15', '1e-14       '])
        call bad('rtol_one', SB//'&integration rtol = 1 /', ['rtol'])
        call bad('atol_negative', SB//'&integration atol = -1e-12 /', ['atol'])
        call bad('bad_logical', SB//'&integration error_estimate = maybe /', ['error_estimate'])
        call bad('sens_control_differences', SB//'&integration sensitivities = ''differences'','// &
                 ' sensitivity_error_control = .true. /', ['sensitivity_error_control', &
                 'differences              ', 'allowed                  '])
        call bad('long_title', "&scene title = '"//repeat('x', 2000)//"' /"//NL//SB// &
                 '&start mode = 1 /', ['&scene     ', 'at most 256'])
        call bad('long_mode', SB//"&start mode = '"//repeat('x', 300)//"' /", &
                 ['&start     ', 'at most 256'])

    contains

        subroutine bad(label, text, words)
            character(len=*), intent(in) :: label, text
            character(len=*), intent(in) :: words(:)
            integer :: i
            character(len=:), allocatable :: path
            path = dir//'/bad_'//label//'.nml'
            call write_text(path, text)
            call read_deck(path, d, stat)
            call t%check('bad: '//label//' is ERR_DECK ('//msg_of(stat)//')', &
                         stat%code == ERR_DECK)
            call t%check('bad: '//label//' error line names the deck ('//msg_of(stat)//')', &
                         index(error_line(path, stat), 'bifilar: error (bad input): '// &
                         path//': ') == 1)
            do i = 1, size(words)
                call t%check('bad: '//label//' message contains "'//trim(words(i))//'" ('// &
                             msg_of(stat)//')', index(msg_of(stat), trim(words(i))) > 0)
            end do
        end subroutine bad

    end subroutine test_bad

    ! ---------------------------------------------------------------------------------------
    subroutine test_echo(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        type(deck_t) :: d, e
        type(status_t) :: stat
        integer :: u, ios, n
        character(len=4096) :: line
        character(len=:), allocatable :: text
        call write_text(dir//'/echo_src.nml', G_SCENE//NL//G_SUSP//NL//G_BODY//NL// &
                        G_START//NL//G_INTEG//NL)
        call read_deck(dir//'/echo_src.nml', d, stat)
        call t%check('echo: source ok', stat%code == STATUS_OK)
        ! the echo, stripped of '# ', is itself a deck that reads back the same values
        open (newunit=u, file=dir//'/echo.txt', status='replace', action='write')
        ios = 0
        call deck_echo(d, u, ios)
        call write_kv(u, 'x', 0.1_dp, ios)
        call write_kv(u, 'n', 42, ios)
        call write_kv(u, 's', 'text  ', ios)
        call write_kv(u, 'yes', .true., ios)
        call write_kv(u, 'no', .false., ios)
        call t%check('echo: writes ok', ios == 0)
        close (u)
        open (newunit=u, file=dir//'/echo.txt', status='old', action='read')
        text = ''
        n = 0
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            n = n + 1
            if (n <= 6) call t%check('echo: comment line', line(1:2) == '# ')
            if (line(1:3) == '# &') then
                text = text//trim(line(3:))//NL
            else if (n > 1) then
                text = text//trim(line)//NL
            end if
        end do
        close (u)
        call t%check('echo: one line per group + path', n >= 6)
        call t%check('echo: real kv', index(text, 'x = 1.0000000000000001E-001') > 0)
        call t%check('echo: int kv', index(text, 'n = 42'//NL) > 0)
        call t%check('echo: char kv', index(text, 's = text'//NL) > 0)
        call t%check('echo: logical kv', index(text, 'yes = yes'//NL) > 0 .and. &
                     index(text, 'no = no'//NL) > 0)
        call write_text(dir//'/echo_back.nml', text(1:index(text, NL//'x = ')))
        call read_deck(dir//'/echo_back.nml', e, stat)
        call t%check('echo: reads back ('//msg_of(stat)//')', stat%code == STATUS_OK)
        call t%check('echo: same title', d%scene%title == e%scene%title)
        call t%check('echo: same analyses', d%scene%analyses == e%scene%analyses)
        call t%check('echo: same reals', d%suspension%b == e%suspension%b .and. &
                     d%suspension%b_prime == e%suspension%b_prime .and. &
                     d%suspension%l == e%suspension%l .and. &
                     d%suspension%l_prime == e%suspension%l_prime .and. &
                     d%suspension%g == e%suspension%g .and. d%body%mass == e%body%mass .and. &
                     all(d%body%inertia == e%body%inertia) .and. d%body%r == e%body%r .and. &
                     d%body%lambda == e%body%lambda .and. all(d%body%btilde == e%body%btilde) &
                     .and. d%body%sway_depth == e%body%sway_depth .and. &
                     d%start%amplitude == e%start%amplitude .and. &
                     d%start%tilt == e%start%tilt .and. all(d%start%theta == e%start%theta) .and. &
                     all(d%start%theta_dot == e%start%theta_dot) .and. &
                     d%integration%tau_end == e%integration%tau_end .and. &
                     d%integration%dtau_out == e%integration%dtau_out .and. &
                     d%integration%rtol == e%integration%rtol .and. &
                     d%integration%atol == e%integration%atol)
        call t%check('echo: same mode and flags', d%start%mode == e%start%mode .and. &
                     (d%integration%error_estimate .eqv. e%integration%error_estimate) .and. &
                     (d%integration%sensitivity_error_control .eqv. &
                      e%integration%sensitivity_error_control))
        call t%check('all_finite: finite', all_finite([1.0_dp, -2.0_dp, huge(1.0_dp)]))
        call t%check('all_finite: empty', all_finite([real(dp) ::]))
    end subroutine test_echo

    subroutine test_atomic(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        character(len=:), allocatable :: path, tmp1, tmp2
        type(status_t) :: stat
        integer :: u, u2, ios
        character(len=64) :: line
        logical :: there(2)
        path = dir//'/atomic.dat'
        tmp1 = path//'.tmp.'//itoa(process_id())//'.1'
        tmp2 = path//'.tmp.'//itoa(process_id())//'.2'
        call execute_command_line('rm -f '//path//' '//path//'.tmp*')
        call atomic_open(path, u, stat)
        call t%check('atomic: open ok', stat%code == STATUS_OK)
        write (u, '(a)') 'first line'
        there = [exists(path), exists(tmp1)]
        call t%check('atomic: only PATH.tmp.PID.1 before commit', there(2) .and. .not. there(1))
        ! a second file of the same name in the same process gets a name of its own
        call atomic_open(path, u2, stat)
        call t%check('atomic: second open of the same path ok', stat%code == STATUS_OK)
        call t%check('atomic: second temporary file PATH.tmp.PID.2', exists(tmp2))
        write (u2, '(a)') 'second writer'
        call atomic_abort(u2, path)
        call t%check('atomic: abort removes only its own temporary file', &
                     all([exists(tmp1), .not. exists(tmp2)]))
        call atomic_commit(u, path, stat)
        call t%check('atomic: commit ok', stat%code == STATUS_OK)
        there = [exists(path), exists(tmp1)]
        call t%check('atomic: file after commit, no temporary file', there(1) .and. .not. there(2))
        open (newunit=u, file=path, status='old', action='read')
        read (u, '(a)', iostat=ios) line
        close (u)
        call t%check('atomic: content', ios == 0 .and. trim(line) == 'first line')

        ! a stale temporary file of this pid (a crashed run long ago) is not reused
        call write_text(tmp1, 'stale')
        call atomic_open(path, u, stat)
        call t%check('atomic: a stale PATH.tmp.PID.1 is skipped', all([stat%code == STATUS_OK, &
                     exists(tmp2)]))
        write (u, '(a)') 'partial'
        call atomic_abort(u, path)
        call t%check('atomic: the stale file is left alone', exists(tmp1))
        call execute_command_line('rm -f '//tmp1)

        ! an aborted rewrite leaves the old file alone and no temporary file
        call atomic_open(path, u, stat)
        write (u, '(a)') 'partial'
        call atomic_abort(u, path)
        there = [exists(path), exists(tmp1)]
        call t%check('atomic: abort keeps old file, no temporary file', &
                     there(1) .and. .not. there(2))
        ! a failed write (iostat /= 0 from the writer) commits nothing
        call atomic_open(path, u, stat)
        write (u, '(a)') 'replacement'
        call atomic_commit(u, path, stat, ios=5001)
        call t%check('atomic: a failed write is ERR_IO', stat%code == ERR_IO)
        call t%check('atomic: a failed write leaves no temporary file', .not. exists(tmp1))
        open (newunit=u, file=path, status='old', action='read')
        read (u, '(a)', iostat=ios) line
        close (u)
        call t%check('atomic: a failed write keeps the old file', trim(line) == 'first line')
        path = dir//'/aborted.dat'
        call execute_command_line('rm -f '//path//' '//path//'.tmp*')
        call atomic_open(path, u, stat)
        write (u, '(a)') 'partial'
        call atomic_abort(u, path)
        there = [exists(path), exists(path//'.tmp.'//itoa(process_id())//'.1')]
        call t%check('atomic: abort leaves neither file', .not. any(there))

        call atomic_open(dir//'/no_such_dir/x.dat', u, stat)
        call t%check('atomic: open in a missing directory is ERR_IO', stat%code == ERR_IO)
        call t%check('atomic: message names the file', index(msg_of(stat), 'x.dat') > 0)
    end subroutine test_atomic

    !> The files of a run (out_files_t): nothing under a final name before the commit, all of
    !! them after it, none of them (and no temporary file) after a discard or a failed
    !! commit, committed files included.
    subroutine test_run_files(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        type(out_files_t) :: fs, fs2
        type(status_t) :: stat
        character(len=:), allocatable :: a, b, c
        integer :: ua, ub, uc
        a = dir//'/run_a.dat'
        b = dir//'/run_b.summary'
        c = dir//'/run_c.dat'
        call execute_command_line('rm -rf '//a//'* '//b//'* '//c//'*')
        call fs%open(a, ua, stat)
        call fs%open(b, ub, stat)
        write (ua, '(a)') 'rows'
        write (ub, '(a)') 'keys'
        call fs%close(ua, 0, stat)
        call t%check('run files: close ok', stat%code == STATUS_OK)
        call fs%close(ub, 0, stat)
        call t%check('run files: nothing under the final names before the commit', &
                     all([.not. exists(a), .not. exists(b)]))
        call t%check('run files: no temporary file left open', count_matching(dir, &
                     'run_[ab].*.tmp.') == 2)
        call fs%commit(stat)
        call t%check('run files: commit ok', stat%code == STATUS_OK)
        call t%check('run files: both files after the commit', all([exists(a), exists(b)]))
        call t%check('run files: count = 2', fs%count() == 2)
        call t%check('run files: no temporary file after the commit', &
                     count_matching(dir, 'run_[ab].*.tmp.') == 0)
        call fs%discard()
        call t%check('run files: discard after the commit removes the committed files', &
                     all([.not. exists(a), .not. exists(b)]))
        ! a failed write in one file: discard removes the open, staged and failed ones
        call fs2%open(a, ua, stat)
        call fs2%open(b, ub, stat)
        call fs2%close(ua, 0, stat)
        call fs2%close(ub, 5001, stat)
        call t%check('run files: a failed write is ERR_IO', stat%code == ERR_IO)
        call fs2%open(c, uc, stat)
        call fs2%discard()
        call t%check('run files: discard leaves no file and no temporary file', &
                     count_matching(dir, 'run_[abc].') == 0)
        ! a rename that fails (the final name is a folder) removes every file of the run
        call execute_command_line('mkdir -p '//c)
        call fs2%open(a, ua, stat)
        call fs2%open(c, uc, stat)
        call fs2%close(ua, 0, stat)
        call fs2%close(uc, 0, stat)
        call fs2%commit(stat)
        call t%check('run files: a failed rename is ERR_IO', stat%code == ERR_IO)
        call t%check('run files: a failed rename leaves no file of the run', &
                     all([.not. exists(a), count_matching(dir, 'run_[ac].*.tmp.') == 0]))
        call execute_command_line('rmdir '//c)
        call make_dir(dir//'/made/by/make_dir', stat)
        call t%check('make_dir: creates the parents (mkdir -p)', all([stat%code == STATUS_OK, &
                     exists(dir//'/made/by/make_dir/.')]))
        call make_dir(dir//'/made/by/make_dir', stat)
        call t%check('make_dir: an existing folder is fine', stat%code == STATUS_OK)
        call write_text(dir//'/made/plain', 'x')
        call make_dir(dir//'/made/plain', stat)
        call t%check('make_dir: a file in the way is ERR_IO', stat%code == ERR_IO)
        call make_dir(dir//'/made/plain/sub', stat)
        call t%check('make_dir: a file as a parent is ERR_IO', stat%code == ERR_IO)
        call execute_command_line('rm -rf '//dir//'/made')
    end subroutine test_run_files

    !> Number of entries of dir whose name matches the grep pattern.
    integer function count_matching(dir, pattern) result(n)
        character(len=*), intent(in) :: dir, pattern
        n = shell_count('ls -a '//dir//' | grep -c "'//pattern//'"', dir)
    end function count_matching

    ! ---------------------------------------------------------------------------------------
    subroutine test_floquet_chart(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        type(deck_t) :: d, e, ref
        type(status_t) :: stat
        integer :: u, ios
        character(len=4096) :: line
        character(len=:), allocatable :: text
        character(len=*), parameter :: SB = MIN_SUSP//NL//MIN_BODY//NL
        character(len=*), parameter :: SA = "&scene analyses = 'simulate floquet chart' /"//NL

        ! valid groups read back; &floquet amplitude and rtol leave &start and &integration
        call write_text(dir//'/fc.nml', SA//SB//"&start amplitude = 20 /"//NL// &
                        '&integration rtol = 1e-8 /'//NL//G_FLOQUET//NL//G_CHART//NL)
        call read_deck(dir//'/fc.nml', d, stat)
        call t%check('floquet/chart: status ok ('//msg_of(stat)//')', stat%code == STATUS_OK)
        if (stat%code /= STATUS_OK) return
        call t%check_close('floquet: amplitude', d%floquet%amplitude, 30.0_dp)
        call t%check('floquet: segments', d%floquet%segments == 8)
        call t%check_close('floquet: rtol', d%floquet%rtol, 1.0e-9_dp)
        call t%check_close('floquet: &start amplitude separate', d%start%amplitude, 20.0_dp)
        call t%check_close('floquet: &integration rtol separate', d%integration%rtol, 1.0e-8_dp)
        call t%check('chart: x lower case', trim(d%chart%x) == 'lambda')
        call t%check('chart: y lower case', trim(d%chart%y) == 'inertia_ratio')
        call t%check_close('chart: x_min', d%chart%x_min, -1.0_dp)
        call t%check_close('chart: x_max', d%chart%x_max, 1.25_dp)
        call t%check_close('chart: y_min', d%chart%y_min, 0.5_dp)
        call t%check_close('chart: y_max', d%chart%y_max, 2.0_dp)
        call t%check('chart: nx, ny', d%chart%nx == 50 .and. d%chart%ny == 60)

        ! the echo carries both groups and reads back the same values
        open (newunit=u, file=dir//'/fc_echo.txt', status='replace', action='write')
        ios = 0
        call deck_echo(d, u, ios)
        close (u)
        open (newunit=u, file=dir//'/fc_echo.txt', status='old', action='read')
        text = ''
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:3) == '# &') text = text//trim(line(3:))//NL
        end do
        close (u)
        call t%check('floquet/chart: echo has &floquet', index(text, '&floquet ') > 0)
        call t%check('floquet/chart: echo has &chart', index(text, '&chart ') > 0)
        call write_text(dir//'/fc_back.nml', text)
        call read_deck(dir//'/fc_back.nml', e, stat)
        call t%check('floquet/chart: echo reads back ('//msg_of(stat)//')', &
                     stat%code == STATUS_OK)
        call t%check('floquet/chart: echo same &floquet', &
                     d%floquet%amplitude == e%floquet%amplitude .and. &
                     d%floquet%segments == e%floquet%segments .and. &
                     d%floquet%rtol == e%floquet%rtol)
        call t%check('floquet/chart: echo same &chart', d%chart%x == e%chart%x .and. &
                     d%chart%y == e%chart%y .and. d%chart%x_min == e%chart%x_min .and. &
                     d%chart%x_max == e%chart%x_max .and. d%chart%y_min == e%chart%y_min .and. &
                     d%chart%y_max == e%chart%y_max .and. d%chart%nx == e%chart%nx .and. &
                     d%chart%ny == e%chart%ny)

        ! defaults when absent; no echo lines when the analyses are not requested
        call write_text(dir//'/fc_absent.nml', SB)
        call read_deck(dir//'/fc_absent.nml', d, stat)
        call t%check('floquet/chart defaults: status ok ('//msg_of(stat)//')', &
                     stat%code == STATUS_OK)
        call t%check('floquet defaults', d%floquet%amplitude == 45.0_dp .and. &
                     d%floquet%segments == 1 .and. d%floquet%rtol == 1.0e-10_dp .and. &
                     d%floquet%amplitude == ref%floquet%amplitude)
        call t%check('chart defaults', trim(d%chart%x) == 'l' .and. &
                     trim(d%chart%y) == 'amplitude' .and. d%chart%x_min == 0.5_dp .and. &
                     d%chart%x_max == 4.0_dp .and. d%chart%y_min == 5.0_dp .and. &
                     d%chart%y_max == 90.0_dp .and. d%chart%nx == ref%chart%nx .and. &
                     d%chart%ny == ref%chart%ny)
        open (newunit=u, file=dir//'/fc_echo2.txt', status='replace', action='write')
        ios = 0
        call deck_echo(d, u, ios)
        close (u)
        open (newunit=u, file=dir//'/fc_echo2.txt', status='old', action='read')
        text = ''
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            text = text//trim(line)//NL
        end do
        close (u)
        call t%check('floquet/chart: no echo when not requested', &
                     index(text, '&floquet') == 0 .and. index(text, '&chart') == 0)
        ! a partial group keeps the other defaults
        call write_text(dir//'/fc_partial.nml', SB//'&chart ny = 7 /'//NL// &
                        '&floquet segments = 3 /'//NL)
        call read_deck(dir//'/fc_partial.nml', d, stat)
        call t%check('floquet/chart partial: ok ('//msg_of(stat)//')', &
                     stat%code == STATUS_OK .and. d%chart%ny == 7 .and. &
                     d%chart%nx == ref%chart%nx .and. d%floquet%segments == 3 .and. &
                     d%floquet%rtol == ref%floquet%rtol)

        ! valid edges of the ranges
        call good('lambda_full', SB//"&chart x = 'lambda', x_min = -1.5707963267948966, " // &
                  'x_max = 1.5707963267948966 /')
        call good('r_zero', SB//"&chart x = 'r', x_min = 0, x_max = 1, y = 'b' /")
        call good('grid_max', SB//'&chart nx = 500, ny = 500 /')
        call good('floquet_edges', SB//'&floquet amplitude = 179.9, segments = 64, ' // &
                  'rtol = 1e-14 /')

        ! bad values: ERR_DECK naming the group and the variable
        call bad('chart_unknown_x', SB//"&chart x = 'length' /", &
                 ['&chart       ', 'x = ''length'' ', 'inertia_ratio'])
        call bad('chart_unquoted_x', SB//'&chart x = l /', ['x = l ', 'quoted'])
        call bad('chart_x_eq_y', SB//"&chart x = 'B', y = 'b' /", &
                 ['&chart y', 'same    ', 'x       '])
        call bad('chart_min_eq_max', SB//'&chart x_min = 2, x_max = 2 /', &
                 ['x_max = 2', 'x_min    '])
        call bad('chart_min_gt_max', SB//'&chart y_min = 50, y_max = 10 /', &
                 ['y_max = 10', 'y_min     '])
        call bad('chart_amplitude_180', SB//'&chart y_max = 200 /', &
                 ['&chart y_max = 200', '180               ', 'amplitude         '])
        call bad('chart_amplitude_zero', SB//"&chart x = 'amplitude', x_min = 0, x_max = 10, " // &
                 "y = 'l', y_min = 1, y_max = 2 /", ['x_min = 0'])
        call bad('chart_l_zero', SB//'&chart x_min = 0 /', ['x_min = 0     ', '0.001 <= x_min'])
        call bad('chart_b_negative', SB//"&chart y = 'b', y_min = -1, y_max = 1 /", &
                 ['y_min = -1'])
        call bad('chart_r_negative', SB//"&chart x = 'r', x_min = -0.1 /", ['x_min = -0.1'])
        call bad('chart_lambda_wide', SB//"&chart x = 'lambda', x_min = -2, x_max = 1 /", &
                 ['x_min = -2', 'lambda    '])
        call bad('chart_lambda_high', SB//"&chart y = 'lambda', y_min = 0, y_max = 1.6 /", &
                 ['y_max = 1.6', 'pi/2       '])
        call bad('chart_inertia_ratio_zero', SB//"&chart y = 'inertia_ratio', y_min = 0, " // &
                 'y_max = 2 /', ['y_min = 0'])
        call bad('chart_nx_one', SB//'&chart nx = 1 /', ['nx = 1 ', '2 <= nx'])
        call bad('chart_ny_big', SB//'&chart ny = 1001 /', ['ny = 1001', '1000     '])
        call bad('chart_grid_big', SB//'&chart nx = 1000, ny = 251 /', &
                 ['&chart ny', 'nx*ny    ', '250000   '])
        call bad('chart_nx_real', SB//'&chart nx = 2.5 /', ['nx = 2.5      ', 'not an integer'])
        call bad('chart_nx_nan', SB//'&chart nx = NaN /', ['nx = NaN      ', 'not an integer'])
        call bad('chart_x_min_nan', SB//'&chart x_min = NaN /', ['x_min = NaN', 'finite     '])
        call bad('chart_y_max_inf', SB//'&chart y_max = Inf /', ['y_max = Inf'])
        call bad('chart_unknown_variable', SB//'&chart n = 3 /', ['''n''', 'nx '])
        call bad('floquet_segments_zero', SB//'&floquet segments = 0 /', &
                 ['&floquet segments = 0', '64                   '])
        call bad('floquet_segments_big', SB//'&floquet segments = 65 /', ['segments = 65'])
        call bad('floquet_segments_real', SB//'&floquet segments = 2.5 /', &
                 ['segments = 2.5', 'not an integer'])
        call bad('floquet_rtol_one', SB//'&floquet rtol = 1 /', &
                 ['&floquet rtol = 1', '1e-2             '])
        call bad('floquet_rtol_small', SB//'&floquet rtol = 1e-15 /', ['rtol = 1e-15'])
        call bad('floquet_rtol_nan', SB//'&floquet rtol = nan /', ['rtol = NaN', 'finite    '])
        call bad('floquet_amplitude_180', SB//'&floquet amplitude = 180 /', &
                 ['&floquet amplitude = 180', '1e-6 <= amplitude < 180 '])
        ! a tiny amplitude: SIGFPE in the variational analysis (found by the fuzz test at
        ! 1.97e-229 degrees); refused, in a chart's axis and a design too
        call bad('floquet_amplitude_tiny', SB//'&floquet amplitude = 1.97e-229 /', &
                 ['&floquet amplitude = 1.97e-229', '1e-6 <= amplitude < 180       '])
        call bad('chart_amplitude_tiny', SB//"&chart y = 'amplitude', y_min = 1e-200 /", &
                 ['y_min = 1e-200             ', '1e-6 <= y_min < y_max < 180'])
        call good('floquet_amplitude_1e-6', SB//'&floquet amplitude = 1e-6 /')
        call bad('floquet_amplitude_text', SB//'&floquet amplitude = big /', &
                 ['amplitude = big', 'not a real     '])
        call bad('floquet_unknown_variable', SB//'&floquet segment = 2 /', &
                 ['segment ', 'segments', '&floquet'])

    contains

        subroutine good(label, text)
            character(len=*), intent(in) :: label, text
            call write_text(dir//'/fc_'//label//'.nml', text)
            call read_deck(dir//'/fc_'//label//'.nml', d, stat)
            call t%check('floquet/chart: valid '//label//' ('//msg_of(stat)//')', &
                         stat%code == STATUS_OK)
        end subroutine good

        subroutine bad(label, text, words)
            character(len=*), intent(in) :: label, text
            character(len=*), intent(in) :: words(:)
            integer :: i
            character(len=:), allocatable :: path
            path = dir//'/bad_'//label//'.nml'
            call write_text(path, text)
            call read_deck(path, d, stat)
            call t%check('bad: '//label//' is ERR_DECK ('//msg_of(stat)//')', &
                         stat%code == ERR_DECK)
            call t%check('bad: '//label//' error line names the deck ('//msg_of(stat)//')', &
                         index(error_line(path, stat), 'bifilar: error (bad input): '// &
                         path//': ') == 1)
            do i = 1, size(words)
                call t%check('bad: '//label//' message contains "'//trim(words(i))//'" ('// &
                             msg_of(stat)//')', index(msg_of(stat), trim(words(i))) > 0)
            end do
        end subroutine bad

    end subroutine test_floquet_chart

    !> &scene model = 'kane' | 'elastic' and the &cables group: read back, defaults, echo,
    !! bad values an ERR_DECK naming the variable and what is allowed.
    subroutine test_cables(t, dir)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: dir
        type(deck_t) :: d
        type(status_t) :: stat
        integer :: u, ios
        character(len=4096) :: line
        logical :: echoed
        character(len=*), parameter :: SB = MIN_SUSP//NL//MIN_BODY//NL
        character(len=*), parameter :: SE = "&scene model = 'Elastic' /"//NL

        call write_text(dir//'/cab.nml', SE//SB//'&cables stiffness = 2.5e7, damping = 0.3 /'//NL)
        call read_deck(dir//'/cab.nml', d, stat)
        call t%check('cables: status ok ('//msg_of(stat)//')', stat%code == STATUS_OK)
        if (stat%code /= STATUS_OK) return
        call t%check('cables: model lower case', trim(d%scene%model) == 'elastic')
        call t%check_close('cables: stiffness', d%cables%stiffness, 2.5e7_dp)
        call t%check_close('cables: damping', d%cables%damping, 0.3_dp)
        ! the echo carries &cables for the elastic model
        open (newunit=u, file=dir//'/cab_echo.txt', status='replace', action='write')
        ios = 0
        call deck_echo(d, u, ios)
        close (u)
        echoed = .false.
        open (newunit=u, file=dir//'/cab_echo.txt', status='old', action='read')
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, '# &cables stiffness = 25000000, damping = 0.3 /') == 1) echoed = .true.
        end do
        close (u)
        call t%check('cables: echoed for model = ''elastic''', echoed)

        call write_text(dir//'/cab_def.nml', SB)
        call read_deck(dir//'/cab_def.nml', d, stat)
        call t%check('cables: defaults ok ('//msg_of(stat)//')', stat%code == STATUS_OK)
        call t%check('cables: default model kane', trim(d%scene%model) == 'kane')
        call t%check_close('cables: default stiffness 1e6', d%cables%stiffness, 1.0e6_dp)
        call t%check_close('cables: default damping 0.05', d%cables%damping, 0.05_dp)
        call write_text(dir//'/cab_kane.nml', "&scene model = 'kane' /"//NL//SB)
        call read_deck(dir//'/cab_kane.nml', d, stat)
        call t%check('cables: model = ''kane'' ok ('//msg_of(stat)//')', stat%code == STATUS_OK)

        call bad('model_elastik', "&scene model = 'elastik' /"//NL//SB, &
                 [character(len=20) :: '&scene model', 'elastik', 'kane', 'elastic'])
        call bad('cables_stiffness_zero', SE//SB//'&cables stiffness = 0 /', &
                 [character(len=20) :: '&cables stiffness', '1 <= stiffness'])
        call bad('cables_stiffness_huge', SE//SB//'&cables stiffness = 1e13 /', &
                 [character(len=20) :: '&cables stiffness', '<= 1e12'])
        call bad('cables_stiffness_nan', SE//SB//'&cables stiffness = NaN /', &
                 [character(len=20) :: '&cables stiffness', 'not a finite'])
        call bad('cables_damping_negative', SE//SB//'&cables damping = -0.1 /', &
                 [character(len=20) :: '&cables damping', '0 <= damping'])
        call bad('cables_damping_big', SE//SB//'&cables damping = 11 /', &
                 [character(len=20) :: '&cables damping', '<= 10'])
        call bad('cables_damping_inf', SE//SB//'&cables damping = Inf /', &
                 [character(len=20) :: '&cables damping', 'not a finite'])
        call bad('cables_unknown_variable', SE//SB//'&cables stifness = 1e6 /', &
                 [character(len=20) :: 'stifness', '&cables'])

    contains

        subroutine bad(label, text, words)
            character(len=*), intent(in) :: label, text
            character(len=*), intent(in) :: words(:)
            integer :: i
            character(len=:), allocatable :: path
            path = dir//'/bad_'//label//'.nml'
            call write_text(path, text)
            call read_deck(path, d, stat)
            call t%check('bad: '//label//' is ERR_DECK ('//msg_of(stat)//')', &
                         stat%code == ERR_DECK)
            do i = 1, size(words)
                call t%check('bad: '//label//' message contains "'//trim(words(i))//'" ('// &
                             msg_of(stat)//')', index(msg_of(stat), trim(words(i))) > 0)
            end do
        end subroutine bad

    end subroutine test_cables

    !> rshort against its definition, the digits tried in turn (k = 0, 1, 2, ... in fixed
    !! notation for 1e-4 <= |x| < 1e15, else in scientific notation), over random bit
    !! patterns of every magnitude, powers of two, decimals of few digits and their
    !! neighbours, thirds and the deck values of the paper's scenes.
    subroutine test_rshort(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: i8 = selected_int_kind(18)
        real(dp) :: x, u(2)
        integer :: k, bad, cases
        integer(i8) :: bits
        character(len=80) :: first
        logical :: halting(size(ieee_usual))
        bad = 0
        cases = 0
        first = ''
        call traps_off(halting)     ! the definition reads 2e308 back: an overflow
        call random_seed(put=[(12345 + 7*k, k=1, 64)])
        do k = 1, 3000
            call random_number(u)
            bits = int(u(1)*2.0_dp**31, i8)*2_i8**32 + int(u(2)*2.0_dp**32, i8)
            x = transfer(bits, 1.0_dp)
            if (x /= x .or. abs(x) > huge(1.0_dp)) cycle
            call one(x)
            call random_number(u)
            call one(10.0_dp**(30.0_dp*u(1) - 10.0_dp)*u(2))
        end do
        do k = -20, 60
            call one(2.0_dp**k)
            call one(-3.0_dp*2.0_dp**k)
        end do
        do k = 0, 2000
            x = real(k, dp)/1000.0_dp
            call one(x)
            call one(nearest(x, 1.0_dp))
            call one(nearest(x, -1.0_dp))
            call one(real(k, dp)/3.0_dp)
            call one(real(k, dp)*1.0e-7_dp)
            call one(real(k, dp)*1.0e12_dp + 0.5_dp)
        end do
        call one(0.1458333333333333_dp)
        call one(sqrt(0.5_dp))
        call one(atan(1.0_dp))
        call one(9.80665_dp)
        call one(0.0_dp)
        call one(-0.0_dp)
        call one(huge(1.0_dp))
        call one(tiny(1.0_dp))
        call traps_restore(halting)
        write (*, '(a,i0,a,i0)') '  rshort: ', cases, ' values, different: ', bad
        if (bad > 0) write (*, '(a)') '  first difference: '//trim(first)
        call t%check('rshort = the digits tried in turn, '//itoa(cases)//' values', &
                     bad == 0 .and. cases > 15000)
    contains
        subroutine one(v)
            real(dp), intent(in) :: v
            character(len=:), allocatable :: got, want
            real(dp) :: y
            integer :: ios, ie
            cases = cases + 1
            got = rshort(v)
            want = by_turns(v)
            read (got, *, iostat=ios) y
            ie = index(got, 'e')
            if (ie > 0) got = got(1:ie - 1)     ! the mantissa (the whole text reads back)
            if (got /= want .or. ios /= 0 .or. y /= v) then
                bad = bad + 1
                if (len_trim(first) == 0) first = got//' against '//want
            end if
        end subroutine one
        !> The definition: the fewest digits that read back, each k tried in turn.
        function by_turns(v) result(s)
            real(dp), intent(in) :: v
            character(len=:), allocatable :: s
            character(len=48) :: buf
            real(dp) :: y
            integer :: kk, ios, ie
            logical :: fixed
            fixed = .false.
            if (v == 0.0_dp .or. (abs(v) >= 1.0e-4_dp .and. abs(v) < 1.0e15_dp)) then
                do kk = 0, 24
                    write (buf, '(f48.'//itoa(kk)//')') v
                    read (buf, *, iostat=ios) y
                    fixed = ios == 0 .and. y == v
                    if (fixed) exit
                end do
            end if
            if (fixed) then
                s = trim(adjustl(buf))
                if (s(1:1) == '.') s = '0'//s
                if (len(s) > 1) then
                    if (s(1:2) == '-.') s = '-0'//s(2:)
                end if
                if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
                return
            end if
            do kk = 0, 16
                write (buf, '(es48.'//itoa(kk)//'e3)') v
                read (buf, *, iostat=ios) y
                if (ios == 0 .and. y == v) exit
            end do
            ! the mantissa only: the exponent's text is rshort's own (tested by the echo)
            s = trim(adjustl(buf))
            ie = index(s, 'E')
            s = s(1:ie - 1)
            if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
        end function by_turns
    end subroutine test_rshort

end module test_deck
