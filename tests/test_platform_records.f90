!> Records of a body off the axis of a quadrifilar (suite platform): the record of the
!! elastic cables' model (module platform_measure's platform_record, four cables), made by
!! the program's own model at the truth I1 = 0.0243, fitted by identify through the program:
!! nearly noise-free (1e-7 rad/s: a record without noise leaves the fit's chi^2 at the runs'
!! own noise, where its last steps may fail) I1 within 1e-6, with noise within U; a body 1e-6 m off the axis (the elastic model)
!! gives the centred body's I1 (the bifilar's pure torsion) from the same record; the
!! cables' stiffness 1e7 against the default 1e6; a body above its tipping height exits 4;
!! quantity 'rates' on a platform exits 2.
module test_platform_records
    use kinds, only: dp
    use status, only: status_t
    use testing, only: tester_t, write_text, exists, fresh_dir, run, message_lines, &
                       file_has, read_kv_text
    use rig, only: rig_t, start_t, accuracy_t
    use platform_measure, only: platform_record
    use random, only: rng_t, rng_stream, rng_normal
    implicit none
    private

    public :: run_platform_record_tests

    character(len=*), parameter :: SCR = 'build/test_platform_records'
    real(dp), parameter :: I1_TRUE = 0.0243_dp

contains

    subroutine run_platform_record_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        if (t%want('platform record: four cables, the body off the axis (elastic)')) &
            call test_quad_record(t, exe)
    end subroutine run_platform_record_tests

    !> The quadrifilar of the tests (R = R' = 0.135 m, l = 1 m, 2.048 kg, the mass centre
    !! 0.05 m below the attachments and e m off the axis along x), I1 = 0.0243.
    pure function quad_rig(e) result(rg)
        real(dp), intent(in) :: e
        type(rig_t) :: rg
        rg%cables = 4
        rg%b = 0.27_dp
        rg%b_prime = 0.27_dp
        rg%l = 1.0_dp
        rg%l_prime = 1.0_dp
        rg%g = 9.81_dp
        rg%mass = 2.048_dp
        rg%inertia = [I1_TRUE, 0.014_dp, 0.014_dp]
        rg%c_v = 0.0_dp
        rg%c_q = 0.0_dp
        rg%r = sqrt((0.135_dp + e)**2 + 0.05_dp**2)
        rg%lambda = atan2(0.05_dp, 0.135_dp + e)
    end function quad_rig

    !> The rate record (rad/s, every 0.02 s for 3 s) of rig rg released at 10 degrees,
    !! plus normal noise sigma (seed 5), written to path with 10 digits as make_record does.
    subroutine write_record(rg, sigma, path, ok)
        type(rig_t), intent(in) :: rg
        real(dp), intent(in) :: sigma
        character(len=*), intent(in) :: path
        logical, intent(out) :: ok
        integer, parameter :: n = 151
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(status_t) :: stat
        type(rng_t) :: g
        real(dp) :: tt(n), v(n)
        integer :: i, u
        do i = 1, n
            tt(i) = 0.02_dp*(i - 1)
        end do
        st%mode = 'raised'
        st%amplitude = 10.0_dp
        call platform_record(rg, st, acc, tt, 0.0_dp, .true., v, stat)
        ok = stat%code == 0 .and. all(abs(v) < 10.0_dp)
        g = rng_stream(5, 0)
        open (newunit=u, file=path, status='replace', action='write')
        write (u, '(a)') '# t (s)  W (rad/s)'
        do i = 1, n
            write (u, '(f10.4,es19.9e3)') tt(i), v(i) + sigma*rng_normal(g)
        end do
        close (u)
    end subroutine write_record

    !> A value of a key = value file as a number (-huge when absent or unreadable).
    real(dp) function kv_real(path, key) result(x)
        character(len=*), intent(in) :: path, key
        character(len=64) :: val
        integer :: ios
        call read_kv_text(path, key, val)
        read (val, *, iostat=ios) x
        if (ios /= 0) x = -huge(1.0_dp)
    end function kv_real

    subroutine test_quad_record(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: NL = new_line('a')
        character(len=*), parameter :: MEAS = "&start mode = 'raised', amplitude = 10 /"// &
            NL//"&measurement quantity = 'rate', estimate = 'I1 amplitude', record = "
        character(len=:), allocatable :: d, o, head
        real(dp) :: iq0, iq, uq, ic, ie, i7
        integer :: ex(6)
        logical :: ok0, ok1
        d = SCR//'/quad'
        call fresh_dir(d)
        o = d//'/out'
        call write_record(quad_rig(0.018_dp), 1.0e-7_dp, d//'/clean.dat', ok0)
        call write_record(quad_rig(0.018_dp), 0.002_dp, d//'/noisy.dat', ok1)
        head = "&scene analyses = 'identify' /"//NL// &
            '&suspension cables = 4, radius = 0.135, radius_prime = 0.135, l = 1.0, '// &
            'g = 9.81 /'//NL//'&body mass = 2.048, inertia = 0.022, 0.014, 0.014, '// &
            'cg_depth = 0.05, '
        call write_text(d//'/clean.nml', head//'cg_offset = 0.018, 0 /'//NL//MEAS// &
            "'clean.dat' /"//NL)
        ex(1) = run(exe//' '//d//'/clean.nml --out '//o, d)
        iq0 = kv_real(o//'/clean.identify', 'I1')
        call write_text(d//'/noisy.nml', head//'cg_offset = 0.018, 0 /'//NL// &
            MEAS//"'noisy.dat' /"//NL)
        ex(2) = run(exe//' '//d//'/noisy.nml --out '//o, d)
        iq = kv_real(o//'/noisy.identify', 'I1')
        uq = kv_real(o//'/noisy.identify', 'U_I1')
        call t%check('platform record: the elastic quadrifilar''s records are made', &
                     ok0 .and. ok1)
        call t%check('platform record: four cables off the axis fit (exit 0)', &
                     all(ex(1:2) == 0))
        call t%check_close('platform record: four cables off the axis, noise 1e-7, I1 to '// &
                           '1e-6', iq0, I1_TRUE, 1.0e-6_dp, 0.0_dp)
        call t%check('platform record: four cables off the axis, with noise, I1 within U', &
                     abs(iq - I1_TRUE) < uq .and. uq > 0.0_dp)
        ! a record of a body 1e-6 m off the axis: the elastic model against pure torsion
        call write_record(quad_rig(1.0e-6_dp), 0.002_dp, d//'/near.dat', ok0)
        call write_text(d//'/c.nml', head//'cg_offset = 0, 0 /'//NL//MEAS//"'near.dat' /"//NL)
        ex(3) = run(exe//' '//d//'/c.nml --out '//o, d)
        ic = kv_real(o//'/c.identify', 'I1')
        call write_text(d//'/e.nml', head//'cg_offset = 1e-6, 0 /'//NL//MEAS// &
            "'near.dat' /"//NL)
        ex(4) = run(exe//' '//d//'/e.nml --out '//o, d)
        ie = kv_real(o//'/e.identify', 'I1')
        call t%check('platform record: 1e-6 m off the axis and centred fit (exit 0)', &
                     ok0 .and. all(ex(3:4) == 0))
        call t%check_close('platform record: 1e-6 m off the axis (elastic) gives the '// &
                           'centred body''s I1 (pure torsion)', ie, ic, 1.0e-6_dp, 0.0_dp)
        ! the cables ten times stiffer
        call write_text(d//'/k7.nml', head//'cg_offset = 0.018, 0 /'//NL// &
            '&cables stiffness = 1e7 /'//NL//MEAS//"'noisy.dat' /"//NL)
        ex(5) = run(exe//' '//d//'/k7.nml --out '//o, d)
        i7 = kv_real(o//'/k7.identify', 'I1')
        call t%check('platform record: stiffness 1e7 fits (exit 0)', ex(5) == 0)
        call t%check_close('platform record: stiffness 1e7 against 1e6 changes I1 by less '// &
                           'than 1e-6', i7, iq, 1.0e-6_dp, 0.0_dp)
        ! (differences, not ratios: a failed fit leaves -huge)
        write (*, '(a,es10.2,a,es16.8,a,es10.3,a,es10.2,a,es10.2)') '  platform record, '// &
            'four cables off the axis: noise 1e-7 I1 - truth ', iq0 - I1_TRUE, &
            ', noisy I1 ', iq, ', U ', uq, '; 1e-6 off less centred ', ie - ic, &
            '; k 1e7 less 1e6 ', i7 - iq
        ! above its tipping height
        call write_text(d//'/tip.nml', "&scene analyses = 'identify' /"//NL// &
            '&suspension cables = 4, radius = 0.135, radius_prime = 0.05, l = 1.0, '// &
            'g = 9.81 /'//NL//'&body mass = 2.048, inertia = 0.022, 0.014, 0.014, '// &
            'cg_depth = -1, cg_offset = 0.001, 0 /'//NL//MEAS//"'noisy.dat' /"//NL)
        ex(6) = run(exe//' '//d//'/tip.nml --out '//o, d)
        call t%check('platform record: four cables off the axis, above the tipping height: '// &
                     'exit 4, one line', all([ex(6) == 4, message_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', 'tips over'), .not. exists(o//'/tip.identify')]))
        ! quantity 'rates': the platform's models give no tilt or sway rates
        call write_text(d//'/rates.nml', head//'cg_offset = 0.018, 0 /'//NL// &
            "&start mode = 'raised', amplitude = 10 /"//NL//"&measurement quantity = "// &
            "'rates', estimate = 'I1 amplitude', record = 'noisy.dat' /"//NL)
        ex(6) = run(exe//' '//d//'/rates.nml --out '//o, d)
        call t%check('platform record: quantity rates on a platform: exit 2, one line', &
                     all([ex(6) == 2, message_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', 'quantity = ''rates'''), &
                     .not. exists(o//'/rates.identify')]))
    end subroutine test_quad_record

end module test_platform_records
