!> Analysis calibrate and the calibrated rig: a rig whose taped spacings b = b' are 0.2 %
!! long (their product 0.4 % high) is calibrated with a disc of known I1; a second body
!! measured on it with &measurement calibration comes out within U of its truth, and 0.4 %
!! off without the calibration; over 20 seeds of timing noise the calibrated I1 covers the
!! truth in at least 17.  The periods are made here from the true rig (exact torsion).  The
!! summary line writes scale = x ± u; a bad value of &calibration is refused with one line
!! naming the deck and the variable, exit 2, no file.
module test_calibrate
    use kinds, only: dp
    use testing, only: tester_t, write_text, run, fresh_dir, exists, file_has, message_lines, &
        noisy, true_periods, periods_text
    use output_io, only: read_kv
    use text, only: rshort, itoa
    implicit none
    private
    public :: run_calibrate_tests

    character(len=*), parameter :: DIR = 'build/test_calibrate'
    real(dp), parameter :: B_TRUE = 0.40_dp, B_TAPED = 0.4008_dp, U_T = 1.0e-4_dp
    real(dp), parameter :: I_DISC = 0.05_dp, I_BODY = 0.08_dp
    real(dp), parameter :: AMPS(3) = [10.0_dp, 20.0_dp, 30.0_dp]

contains

    subroutine run_calibrate_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        if (t%want('calibrate: a rig calibrated with a disc, a second body within U')) &
            call calibrated_rig_test(t, exe)
        if (t%want('calibrate: the summary line, bad &calibration values')) &
            call words_test(t, exe)
    end subroutine run_calibrate_tests

    !> The summary line and the refusals of bad &calibration values.
    subroutine words_test(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp) :: tdisc(3)
        logical :: ok
        call execute_command_line('mkdir -p '//DIR)
        call true_periods(DIR, 'disc', 2.5_dp, I_DISC, AMPS, tdisc, ok)
        call t%check('calibrate: true periods of the disc made', ok)
        if (.not. ok) return
        call check_summary(t, exe, tdisc)
        call bad_calibration(t, exe, tdisc)
    end subroutine words_test

    subroutine calibrated_rig_test(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp) :: tdisc(3), tbody(3), i1, big_u, scale, i1_no, u_no
        integer :: seed, covered, ex
        logical :: ok, found
        call fresh_dir(DIR)
        call true_periods(DIR, 'disc', 2.5_dp, I_DISC, AMPS, tdisc, ok)
        call true_periods(DIR, 'body', 3.2_dp, I_BODY, AMPS, tbody, ok)
        call t%check('calibrate: true periods made', ok)
        if (.not. ok) return
        covered = 0
        do seed = 1, 20
            call write_text(DIR//'/cal.nml', head('cal', 'calibrate', 2.5_dp, I_DISC)// &
                periods_text(noisy(tdisc, U_T, seed, 1))//' /'//new_line('a')// &
                '&calibration reference_I1 = 0.05, u_reference_I1 = 0.00005 /'//new_line('a'))
            ex = run(exe//' '//DIR//'/cal.nml --out '//DIR, DIR)
            if (ex /= 0) then
                call t%check('calibrate: seed '//itoa(seed)//' runs', .false.)
                return
            end if
            call read_kv(DIR//'/cal.calibration', 'scale', scale, found)
            call write_text(DIR//'/body.nml', head('body', 'identify', 3.2_dp, 0.07_dp)// &
                periods_text(noisy(tbody, U_T, seed, 2))//', calibration = ''cal.calibration'' /'// &
                new_line('a'))
            ex = run(exe//' '//DIR//'/body.nml --out '//DIR, DIR)
            call read_kv(DIR//'/body.identify', 'I1', i1, found)
            call read_kv(DIR//'/body.identify', 'U_I1', big_u, found)
            if (ex /= 0 .or. .not. found) then
                call t%check('calibrate: the calibrated deck runs (seed '//itoa(seed)//')', .false.)
                return
            end if
            if (abs(i1 - I_BODY) <= big_u) covered = covered + 1
            if (seed == 1) then
                call t%check('calibrate: the scale of b b'' is the taped error (1/1.004)', &
                    abs(scale*(B_TAPED/B_TRUE)**2 - 1.0_dp) < 3.0e-3_dp)
                call t%check('calibrate: the calibration''s row in the budget', &
                    has_row(DIR//'/body.identify'))
                call t%check('calibrate: a second body within U of its truth (seed 1)', &
                    abs(i1 - I_BODY) <= big_u)
                call write_text(DIR//'/raw.nml', head('raw', 'identify', 3.2_dp, 0.07_dp)// &
                    periods_text(noisy(tbody, U_T, seed, 2))//' /'//new_line('a'))
                ex = run(exe//' '//DIR//'/raw.nml --out '//DIR, DIR)
                call read_kv(DIR//'/raw.identify', 'I1', i1_no, found)
                call read_kv(DIR//'/raw.identify', 'U_I1', u_no, found)
                call t%check('calibrate: without the calibration 0.4 % off, beyond U', &
                    ex == 0 .and. abs(i1_no/I_BODY - 1.004_dp) < 1.0e-3_dp .and. &
                    abs(i1_no - I_BODY) > u_no)
            end if
        end do
        call t%check('calibrate: over 20 seeds the calibrated I1 covers the truth in >= 17 ('// &
                     itoa(covered)//')', covered >= 17)
        call t%check('calibrate: the certificate written', exists(DIR//'/cal.certificate.html'))
    end subroutine calibrated_rig_test

    !> The summary line writes the scale with its u as identify writes I1: x ± u.
    subroutine check_summary(t, exe, tdisc)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp), intent(in) :: tdisc(3)
        integer :: ex
        logical :: scale, pm, plus_minus
        call write_text(DIR//'/sum.nml', head('sum', 'calibrate', 2.5_dp, I_DISC)// &
            periods_text(tdisc)//' /'//new_line('a')// &
            '&calibration reference_I1 = 0.05, u_reference_I1 = 0.00005 /'//new_line('a'))
        ex = run(exe//' '//DIR//'/sum.nml --out '//DIR, DIR)
        scale = file_has(DIR//'/stdout', 'scale = ')
        pm = file_has(DIR//'/stdout', ' ± ')
        plus_minus = file_has(DIR//'/stdout', '+-')
        call t%check('calibrate: the summary line writes scale = x ± u, as identify writes I1', &
                     ex == 0 .and. scale .and. pm .and. .not. plus_minus)
    end subroutine check_summary

    !> A bad value of &calibration: one line on standard error naming the deck and the
    !! variable, exit 2, no output file.
    subroutine bad_calibration(t, exe, tdisc)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp), intent(in) :: tdisc(3)
        character(len=*), parameter :: CASES(6) = [character(len=72) :: &
            'reference_I1 = -0.05, u_reference_I1 = 0.00005', &
            'reference_I1 = 0.05, u_reference_I1 = 0.06', &
            'reference_I1 = 0.05, test_mass = 0.2, test_radii = 0.05, 0.1, 0.15', &
            'test_mass = 0.2, u_test_mass = 0.001, test_radii = 0.05', &
            'test_mass = 0.2, u_test_mass = 0.001, test_radii = 0.05, -0.1, 0.15', &
            'reference_I1 = ''big'', u_reference_I1 = 0.00005']
        character(len=*), parameter :: VARS(6) = [character(len=16) :: 'reference_i1', &
            'u_reference_i1', 'reference_i1', 'test_radii', 'test_radii', 'reference_i1']
        integer :: k, ex
        logical :: one, none, named
        do k = 1, size(CASES)
            call execute_command_line('rm -f '//DIR//'/bad.calibration '//DIR// &
                                      '/bad.certificate.html')
            call write_text(DIR//'/bad.nml', head('bad', 'calibrate', 2.5_dp, I_DISC)// &
                periods_text(tdisc)//' /'//new_line('a')//'&calibration '//trim(CASES(k))// &
                ' /'//new_line('a'))
            ex = run(exe//' '//DIR//'/bad.nml --out '//DIR, DIR)
            one = message_lines(DIR//'/stderr') == 1
            none = .not. exists(DIR//'/bad.calibration')
            if (exists(DIR//'/bad.certificate.html')) none = .false.
            named = lower_has(DIR//'/stderr', 'bad.nml')
            if (.not. lower_has(DIR//'/stderr', trim(VARS(k)))) named = .false.
            call t%check('calibrate: &calibration '//trim(CASES(k))//': exit 2, one line '// &
                         'naming the deck and '//trim(VARS(k))//', no file', &
                         ex == 2 .and. one .and. none .and. named)
        end do
    end subroutine bad_calibration

    !> Whether the file's text, in lower case, holds w.
    logical function lower_has(path, w)
        character(len=*), intent(in) :: path, w
        integer :: u, ios, i
        character(len=4096) :: line
        lower_has = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            do i = 1, len_trim(line)
                if (line(i:i) >= 'A' .and. line(i:i) <= 'Z') &
                    line(i:i) = achar(iachar(line(i:i)) + 32)
            end do
            if (index(line, w) > 0) lower_has = .true.
        end do
        close (u)
    end function lower_has

    !> A deck's head on the taped rig.
    function head(name, analysis, mass, i1) result(s)
        character(len=*), intent(in) :: name, analysis
        real(dp), intent(in) :: mass, i1
        character(len=:), allocatable :: s
        s = '&scene title = '''//name//''', analyses = '''//analysis//''' /'//new_line('a')// &
            '&suspension b = '//rshort(B_TAPED)//', b_prime = '//rshort(B_TAPED)// &
            ', l = 1.2, l_prime = 1.2, g = 9.80665 /'//new_line('a')// &
            '&body mass = '//rshort(mass)//', inertia = '//rshort(i1)//', 0.05, 0.04, '// &
            'cg_depth = 0.02, cg_offset = 0.0 /'//new_line('a')// &
            '&measurement u_mass = 0.001, u_l = 0.001, u_l_prime = 0.001, u_b = 0.0005, '// &
            'u_b_prime = 0.0005, u_period = '//rshort(U_T)//', amplitudes = 10, 20, 30,'
    end function head



    logical function has_row(path)
        character(len=*), intent(in) :: path
        integer :: u, ios
        character(len=512) :: line
        has_row = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, 'calibration ') == 1) has_row = .true.
        end do
        close (u)
    end function has_row

end module test_calibrate
