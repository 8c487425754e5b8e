!> Every fit checks itself, and the budget is checked against the whole fit: a common
!! amplitude scale (u_amplitude_scale, estimate = 'I1 amplitude_scale') in periods decks
!! and tables of releases; the self-check of a record fit whose samples state their u and
!! of a tensor fit (consistent, and with one sample or one hang mistyped: named,
!! inflated, the truth covered); the budget's sensitivities of a record deck and of a
!! table of releases against central differences of the whole run.  Truths are made here:
!! periods by the exact torsion period, records by the model, hangs by the hang model,
!! noise drawn here.
module test_selfcheck
    use kinds, only: dp
    use status, only: status_t
    use testing, only: tester_t, write_text, file_has, run, fresh_dir, exists, &
        message_lines, read_kv_text, num => full_text
    use deck, only: deck_t, read_deck_text
    use deck_runs, only: rig_of, start_of, accuracy_of
    use driver, only: run_deck
    use identify, only: warning_t
    use random, only: rng_t, rng_stream, rng_normal
    use period_inversion, only: torsion_period_s
    use record_fit, only: record_model
    use rig, only: rig_t, accuracy_t
    use hang_model, only: tensor_entries, hang_rig, hang_period
    use measurement, only: hang_t
    use tensor_fit, only: along_for
    use output_io, only: read_kv
    use text, only: itoa
    implicit none
    private

    public :: run_selfcheck_tests

    character(len=*), parameter :: SCR = 'build/test_selfcheck'
    character(len=*), parameter :: NL = new_line('a')
    real(dp), parameter :: I1_TRUE = 0.0512_dp
    !> The amplitudes' scale of the tests: every amplitude read 1.4 % high.
    real(dp), parameter :: SCALE_OFF = 1.014_dp
    !> A laboratory rig in SI units, symmetric (equal cables, the mass centre on the axis).
    character(len=*), parameter :: SUSP = &
        '&suspension b = 0.4, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL
    character(len=*), parameter :: BODY = &
        '&body mass = 3.1, inertia = 0.0512, 0.063, 0.0304, cg_depth = 0.15 /'//NL
    character(len=*), parameter :: HEAD = "&scene title = 'self-check test', "// &
        "analyses = 'identify' /"//NL
    !> Periods timed at these amplitudes (degrees, as they truly were).
    real(dp), parameter :: AMPS(5) = [10.0_dp, 20.0_dp, 30.0_dp, 40.0_dp, 50.0_dp]
    !> The tensor tests' body and rig.
    real(dp), parameter :: T_MASS = 3.0_dp, T_G = 9.80665_dp
    real(dp), parameter :: T_MOMENTS(3) = [0.08_dp, 0.11_dp, 0.14_dp]
    character(len=*), parameter :: T_RIG = &
        '&suspension b = 0.5, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL// &
        '&body mass = 3.0, inertia = 0.08, 0.11, 0.14, cg_depth = 0.1, cg_offset = 0 /'//NL

contains

    !> Suite selfcheck.
    subroutine run_selfcheck_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        call fresh_dir(SCR)
        if (t%want('selfcheck: an amplitude scale 1.4 % off, known to its u')) &
            call test_scale_known(t)
        if (t%want('selfcheck: the amplitude scale estimated')) call test_scale_estimated(t)
        if (t%want('selfcheck: the amplitude scale in a table of releases')) &
            call test_scale_table(t)
        if (t%want('selfcheck: the amplitude scale refused with one line')) &
            call test_scale_refused(t, exe)
        if (t%want('selfcheck: a record with its samples'' u checks itself')) &
            call test_record_check(t)
        if (t%want('selfcheck: a tensor fit checks itself')) call test_tensor_check(t, exe)
        if (t%want('selfcheck: a record''s budget against the whole fit')) &
            call test_record_fd(t)
        if (t%want('selfcheck: a table''s budget against the whole fit')) call test_table_fd(t)
    end subroutine run_selfcheck_tests

    ! ------------------------------------------------------------------ helpers

    !> The exact torsion period (s) of the SUSP/BODY rig with I1 = i1 at amplitude a (deg).
    real(dp) function period_of(i1, a) result(tp)
        real(dp), intent(in) :: i1, a
        type(deck_t) :: d
        type(status_t) :: st
        call read_deck_text(SCR//'/rig.nml', HEAD//SUSP//BODY, d, st)
        call torsion_period_s(rig_of(d), i1, a, tp, st)
        if (st%code /= 0) tp = -1.0_dp
    end function period_of

    !> The value of key in SCR/NAME.identify (-1e300 when absent).
    real(dp) function kv(name, key) result(v)
        character(len=*), intent(in) :: name, key
        logical :: found
        call read_kv(SCR//'/'//name, key, v, found)
        if (.not. found) v = -1.0e300_dp
    end function kv

    !> A deck written here run in-process into SCR; its warnings.
    subroutine run_here(name, text, st, w)
        character(len=*), intent(in) :: name, text
        type(status_t), intent(out) :: st
        type(warning_t), allocatable, intent(out) :: w(:)
        character(len=:), allocatable :: line
        call write_text(SCR//'/'//name//'.nml', text)
        call run_deck(SCR//'/'//name//'.nml', SCR, line, st, warnings=w)
        if (.not. allocated(w)) allocate (w(0))
    end subroutine run_here

    !> Whether one of the warnings holds word.
    logical function warned(w, word)
        type(warning_t), intent(in) :: w(:)
        character(len=*), intent(in) :: word
        integer :: k
        warned = .false.
        do k = 1, size(w)
            if (index(w(k)%s, word) > 0) warned = .true.
        end do
    end function warned

    !> A budget row of a NAME.identify: field 3 (sensitivity) or 4 (contribution); -1e300
    !! when the row is absent; count: how many rows carry that label.
    subroutine budget_row(path, label, sens, contribution, count)
        character(len=*), intent(in) :: path, label
        real(dp), intent(out) :: sens, contribution
        integer, intent(out) :: count
        character(len=512) :: line
        character(len=32) :: first
        real(dp) :: f(4)
        integer :: u, ios
        sens = -1.0e300_dp
        contribution = -1.0e300_dp
        count = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#' .or. index(line, '=') > 0) cycle
            read (line, *, iostat=ios) first, f
            if (ios /= 0 .or. trim(first) /= label) cycle
            sens = f(3)
            contribution = f(4)
            count = count + 1
        end do
        close (u)
    end subroutine budget_row

    !> periods = ..., amplitudes = ... of the SUSP/BODY rig at AMPS, timing noise u_t drawn
    !! with seed, the amplitudes as read on a scale SCALE_OFF.
    function periods_text(seed, u_t) result(s)
        integer, intent(in) :: seed
        real(dp), intent(in) :: u_t
        character(len=:), allocatable :: s
        character(len=:), allocatable :: per, amp
        type(rng_t) :: g
        integer :: i
        g = rng_stream(seed, 0)
        per = ''
        amp = ''
        do i = 1, size(AMPS)
            per = per//num(period_of(I1_TRUE, AMPS(i)) + u_t*rng_normal(g))//', '
            amp = amp//num(SCALE_OFF*AMPS(i))//', '
        end do
        s = 'periods = '//per//'amplitudes = '//amp
    end function periods_text

    ! ------------------------------------------------------------------ amplitude scale

    !> Periods at 10 ... 50 degrees whose amplitudes were read 1.4 % high, timed to 1e-4 s.
    !! Without u_amplitude_scale the amplitude correction is biased (printed); with
    !! u_amplitude_scale = 0.014 the fit takes the scale as known to that u: consistent,
    !! one budget row amplitude_scale, and I1 +- U covers the truth.  That row's sensitivity
    !! against a central difference of two whole runs with every amplitude scaled by
    !! 1 +- 1e-3.
    subroutine test_scale_known(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        type(warning_t), allocatable :: w(:)
        character(len=:), allocatable :: m
        real(dp) :: c, cont, ip, im, h
        integer :: nrow, i
        type(rng_t) :: g
        character(len=:), allocatable :: per, amp_p, amp_m
        m = periods_text(7, 1.0e-4_dp)
        call run_here('sc0', HEAD//SUSP//BODY//'&measurement '//m//'u_period = 1e-4 /'//NL, &
                      st, w)
        write (*, '(a,es10.3,a,es10.3)') '   amplitudes 1.4 % high, no u_amplitude_scale: '// &
            'I1 - truth = ', kv('sc0.identify', 'I1') - I1_TRUE, ', U_I1 = ', &
            kv('sc0.identify', 'U_I1')
        call run_here('sc1', HEAD//SUSP//BODY//'&measurement '//m//'u_period = 1e-4, '// &
                      'u_amplitude_scale = 0.014 /'//NL, st, w)
        call t%check('scale known: runs', st%code == 0)
        if (st%code /= 0) return
        write (*, '(a,es10.3,a,es10.3)') '   with u_amplitude_scale = 0.014: I1 - truth = ', &
            kv('sc1.identify', 'I1') - I1_TRUE, ', U_I1 = ', kv('sc1.identify', 'U_I1')
        call t%check('scale known: I1 +- U covers the truth', &
                     abs(kv('sc1.identify', 'I1') - I1_TRUE) <= kv('sc1.identify', 'U_I1'))
        call t%check('scale known: the periods consistent with the scale''s u', &
                     file_has(SCR//'/sc1.identify', 'fit_consistency = consistent') .and. &
                     size(w) == 0)
        call budget_row(SCR//'/sc1.identify', 'amplitude_scale', c, cont, nrow)
        call t%check('scale known: one row amplitude_scale, u 0.014', nrow == 1 .and. &
                     abs(cont - 0.014_dp*abs(c)) <= 1.0e-12_dp*abs(cont))
        ! the whole runs with every amplitude scaled by 1 +- h (the same timings)
        h = 1.0e-3_dp
        g = rng_stream(7, 0)
        per = ''
        amp_p = ''
        amp_m = ''
        do i = 1, size(AMPS)
            per = per//num(period_of(I1_TRUE, AMPS(i)) + 1.0e-4_dp*rng_normal(g))//', '
            amp_p = amp_p//num((1.0_dp + h)*SCALE_OFF*AMPS(i))//', '
            amp_m = amp_m//num((1.0_dp - h)*SCALE_OFF*AMPS(i))//', '
        end do
        call run_here('sc1p', HEAD//SUSP//BODY//'&measurement periods = '//per// &
                      'amplitudes = '//amp_p//'u_period = 1e-4, u_amplitude_scale = 0.014 /'// &
                      NL, st, w)
        ip = kv('sc1p.identify', 'I1')
        call run_here('sc1m', HEAD//SUSP//BODY//'&measurement periods = '//per// &
                      'amplitudes = '//amp_m//'u_period = 1e-4, u_amplitude_scale = 0.014 /'// &
                      NL, st, w)
        im = kv('sc1m.identify', 'I1')
        write (*, '(a,es14.6,a,es14.6)') '   dI1/dk: budget ', c, ', whole runs ', &
            (ip - im)/(2*h)
        call t%check_close('scale known: the row''s sensitivity, a difference of whole runs', &
                           c, (ip - im)/(2*h), rtol=1.0e-3_dp)
    end subroutine test_scale_known

    !> The same periods with estimate = 'I1 amplitude_scale': the scale comes back within
    !! 3 u of the truth (1/1.014: the factor that makes the readings true), I1 within U.
    subroutine test_scale_estimated(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        type(warning_t), allocatable :: w(:)
        real(dp) :: k, uk
        call run_here('se1', HEAD//SUSP//BODY//'&measurement '//periods_text(7, 1.0e-4_dp)// &
                      "u_period = 1e-4, estimate = 'I1 amplitude_scale' /"//NL, st, w)
        call t%check('scale estimated: runs', st%code == 0)
        if (st%code /= 0) return
        k = kv('se1.identify', 'amplitude_scale')
        uk = kv('se1.identify', 'u_amplitude_scale')
        write (*, '(a,f10.6,a,es9.2,a,f10.6,a,es10.3,a,es10.3)') '   scale estimated ', k, &
            ' +- ', uk, ' (true ', 1.0_dp/SCALE_OFF, '); I1 - truth = ', &
            kv('se1.identify', 'I1') - I1_TRUE, ', U_I1 = ', kv('se1.identify', 'U_I1')
        call t%check('scale estimated: within 3 u of the truth', uk > 0.0_dp .and. &
                     abs(k - 1.0_dp/SCALE_OFF) <= 3.0_dp*uk)
        call t%check('scale estimated: I1 +- U covers the truth', &
                     abs(kv('se1.identify', 'I1') - I1_TRUE) <= kv('se1.identify', 'U_I1'))
        call t%check('scale estimated: the fit consistent', &
                     file_has(SCR//'/se1.identify', 'fit_consistency = consistent'))
    end subroutine test_scale_estimated

    !> Three releases of such periods in a table (independent timing noise), read on the
    !! same scale 1.4 % high: with u_amplitude_scale the row appears once, as large as one
    !! release's (the scale is common: not averaged down), and I1 +- U covers the truth;
    !! with estimate = 'I1 amplitude_scale' the pooled scale within 3 u, I1 within U.
    subroutine test_scale_table(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        type(warning_t), allocatable :: w(:)
        character(len=:), allocatable :: tab
        type(rng_t) :: g
        real(dp) :: c1, cont1, c3, cont3, k, uk
        integer :: r, i, nrow
        tab = 'trial,period,amplitude,u_period'//NL
        do r = 1, 3
            g = rng_stream(20 + r, 0)
            do i = 1, size(AMPS)
                tab = tab//itoa(r)//','//num(period_of(I1_TRUE, AMPS(i)) + &
                    1.0e-4_dp*rng_normal(g))//','//num(SCALE_OFF*AMPS(i))//',1e-4'//NL
            end do
        end do
        call write_text(SCR//'/st.csv', tab)
        call run_here('st1', HEAD//SUSP//BODY//"&measurement trials = 'st.csv', "// &
                      'u_amplitude_scale = 0.014 /'//NL, st, w)
        call t%check('scale table: runs', st%code == 0)
        if (st%code /= 0) return
        call t%check('scale table: I1 +- U covers the truth', &
                     abs(kv('st1.identify', 'I1') - I1_TRUE) <= kv('st1.identify', 'U_I1'))
        call budget_row(SCR//'/st1.identify', 'amplitude_scale', c3, cont3, nrow)
        call run_here('st0', HEAD//SUSP//BODY//'&measurement '//periods_text(21, 1.0e-4_dp)// &
                      'u_period = 1e-4, u_amplitude_scale = 0.014 /'//NL, st, w)
        call budget_row(SCR//'/st0.identify', 'amplitude_scale', c1, cont1, i)
        write (*, '(a,es10.3,a,es10.3)') '   amplitude_scale row: 3 releases ', cont3, &
            ', one release ', cont1
        call t%check('scale table: one row, not averaged down (within 10 % of one '// &
                     'release''s)', nrow == 1 .and. abs(cont3 - cont1) <= 0.1_dp*cont1)
        call run_here('st2', HEAD//SUSP//BODY//"&measurement trials = 'st.csv', "// &
                      "estimate = 'I1 amplitude_scale' /"//NL, st, w)
        call t%check('scale table estimated: runs', st%code == 0)
        if (st%code /= 0) return
        k = kv('st2.identify', 'amplitude_scale')
        uk = kv('st2.identify', 'u_amplitude_scale')
        write (*, '(a,f10.6,a,es9.2,a,es10.3,a,es10.3)') '   table: scale ', k, ' +- ', uk, &
            '; I1 - truth = ', kv('st2.identify', 'I1') - I1_TRUE, ', U_I1 = ', &
            kv('st2.identify', 'U_I1')
        call t%check('scale table estimated: within 3 u of the truth', uk > 0.0_dp .and. &
                     abs(k - 1.0_dp/SCALE_OFF) <= 3.0_dp*uk)
        call t%check('scale table estimated: I1 +- U covers the truth', &
                     abs(kv('st2.identify', 'I1') - I1_TRUE) <= kv('st2.identify', 'U_I1'))
    end subroutine test_scale_table

    !> Bad values through the executable: one line, exit 2, no output file.
    subroutine test_scale_refused(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: one_amp
        integer :: i
        one_amp = 'periods = '
        do i = 1, 3
            one_amp = one_amp//num(period_of(I1_TRUE, 30.0_dp))//', '
        end do
        one_amp = one_amp//'amplitudes = 30, 30, 30, u_period = 1e-4, '
        call one('negative', 'u_amplitude_scale = -0.01', 'u_amplitude_scale')
        call one('above 0.5', 'u_amplitude_scale = 0.6', 'u_amplitude_scale')
        call one('estimated at one amplitude', one_amp//"estimate = 'I1 amplitude_scale'", &
                 'all at 30')
        call one('a table at one amplitude', "trials = 'one.csv', estimate = 'I1 "// &
                 "amplitude_scale'", 'all at 30')
        call one('with a record', "record = 'none.csv', u_amplitude_scale = 0.01", &
                 'not of a record')
        call one('known and estimated', periods_text(7, 1.0e-4_dp)//"u_period = 1e-4, "// &
                 "estimate = 'I1 amplitude_scale', u_amplitude_scale = 0.01", 'one of them')
    contains
        subroutine one(what, keys, word)
            character(len=*), intent(in) :: what, keys, word
            character(len=:), allocatable :: dd
            integer :: ex
            logical :: l1, l2, l3
            dd = SCR//'/refused'
            call fresh_dir(dd)
            call write_text(dd//'/one.csv', 'trial,period,amplitude'//NL//'1,'// &
                            num(period_of(I1_TRUE, 30.0_dp))//',30'//NL//'1,'// &
                            num(period_of(I1_TRUE, 30.0_dp))//',30'//NL//'1,'// &
                            num(period_of(I1_TRUE, 30.0_dp))//',30'//NL)
            call write_text(dd//'/r.nml', HEAD//SUSP//BODY//'&measurement '// &
                            keys//' /'//NL)
            ex = run(exe//' '//dd//'/r.nml --out '//dd//'/out', dd)
            l1 = message_lines(dd//'/stderr') == 1
            l2 = file_has(dd//'/stderr', word)
            l3 = exists(dd//'/out/r.identify')
            call t%check('scale refused ('//what//'): exit 2, one line naming '//word// &
                         ', no file', ex == 2 .and. l1 .and. l2 .and. .not. l3)
        end subroutine one
    end subroutine test_scale_refused

    ! ------------------------------------------------------------------ records

    !> The SUSP/BODY rig released from 20 deg, its gyro's W (rad/s) for 10 s at 50 Hz with
    !! noise 0.002 rad/s (seed 41), each sample's u 0.002 in a third column; with `typo`
    !! the sample at row 201 (t = 4 s) 0.2 rad/s off.
    subroutine record_text(typo, s, st)
        logical, intent(in) :: typo
        character(len=:), allocatable, intent(out) :: s
        type(status_t), intent(out) :: st
        type(deck_t) :: d
        type(rng_t) :: g
        real(dp), allocatable :: tt(:), w(:)
        integer :: i, n
        s = ''
        call read_deck_text(SCR//'/rec_truth.nml', HEAD//SUSP//BODY//"&start mode = "// &
                            "'raised', amplitude = 20 /"//NL//'&integration rtol = 1e-12, '// &
                            'atol = 1e-14 /'//NL, d, st)
        if (st%code /= 0) return
        n = 501
        allocate (tt(n), w(n))
        do i = 1, n
            tt(i) = (i - 1)/50.0_dp
        end do
        call record_model(rig_of(d), start_of(d), accuracy_of(d), tt, 0.0_dp, .true., w, st)
        if (st%code /= 0) return
        g = rng_stream(41, 0)
        s = 't,w,u'//NL
        do i = 1, n
            w(i) = w(i) + 0.002_dp*rng_normal(g)
            if (typo .and. i == 201) w(i) = w(i) + 0.2_dp
            s = s//num(tt(i))//','//num(w(i))//',0.002'//NL
        end do
    end subroutine record_text

    !> A deck fitting record `rec` (quantity rate, the u column named) with `more`.
    function record_deck(rec, more) result(s)
        character(len=*), intent(in) :: rec, more
        character(len=:), allocatable :: s
        s = HEAD//SUSP//BODY//"&start mode = 'raised', amplitude = 20 /"//NL// &
            "&integration rtol = 1e-10, atol = 1e-12 /"//NL//"&measurement record = '"// &
            rec//"', quantity = 'rate', estimate = 'I1 amplitude', u_l = 0.001, "// &
            'u_b = 0.0005, '//more//' /'//NL
    end function record_deck

    !> A record whose samples state their u: consistent, with fit_consistency and the Birge
    !! ratio written; with one sample mistyped: inconsistent, the warning names its time,
    !! I1 +- U covers the truth; without the u column: not tested.
    subroutine test_record_check(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        type(warning_t), allocatable :: w(:)
        character(len=:), allocatable :: s
        logical :: l1, l2
        call record_text(.false., s, st)
        call write_text(SCR//'/rc_clean.csv', s)
        call run_here('rc_clean', record_deck('rc_clean.csv', 'record_columns = 1, 2, 3'), &
                      st, w)
        call t%check('record check: a clean record runs', st%code == 0)
        if (st%code /= 0) return
        write (*, '(a,f8.4)') '   clean record: Birge ratio ', &
            kv('rc_clean.identify', 'fit_birge_ratio')
        l1 = file_has(SCR//'/rc_clean.identify', 'fit_consistency = consistent')
        l2 = kv('rc_clean.identify', 'fit_birge_ratio') > 0.0_dp
        call t%check('record check: a clean record is consistent, no warning', &
                     l1 .and. l2 .and. size(w) == 0)
        call t%check('record check: the clean record covers the truth', &
                     abs(kv('rc_clean.identify', 'I1') - I1_TRUE) <= &
                     kv('rc_clean.identify', 'U_I1'))
        call record_text(.true., s, st)
        call write_text(SCR//'/rc_typo.csv', s)
        call run_here('rc_typo', record_deck('rc_typo.csv', 'record_columns = 1, 2, 3'), &
                      st, w)
        call t%check('record check: a record with a typo runs', st%code == 0)
        if (st%code /= 0) return
        write (*, '(a,f8.4,a,es10.3,a,es10.3)') '   one sample 100 u off: Birge ratio ', &
            kv('rc_typo.identify', 'fit_birge_ratio'), ', I1 - truth = ', &
            kv('rc_typo.identify', 'I1') - I1_TRUE, ', U_I1 = ', kv('rc_typo.identify', 'U_I1')
        call t%check('record check: the typo makes it inconsistent', &
                     file_has(SCR//'/rc_typo.identify', 'fit_consistency = inconsistent'))
        call t%check('record check: the warning names the sample at t = 4 s', &
                     warned(w, 'do not agree with its samples'' u') .and. &
                     warned(w, 't = 4.000000E+00 s'))
        call t%check('record check: with the typo I1 +- U covers the truth', &
                     abs(kv('rc_typo.identify', 'I1') - I1_TRUE) <= &
                     kv('rc_typo.identify', 'U_I1'))
        call run_here('rc_nou', record_deck('rc_clean.csv', 'record_columns = 1, 2'), st, w)
        l1 = file_has(SCR//'/rc_nou.identify', 'fit_consistency = not tested')
        call t%check('record check: without a u column, not tested', st%code == 0 .and. l1)
    end subroutine test_record_check

    !> The record deck's budget rows b and l against central differences of the whole fit
    !! (the deck's b, or l alone, moved by 1e-4 relative; each run fits the record again).
    subroutine test_record_fd(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        type(warning_t), allocatable :: w(:)
        character(len=:), allocatable :: s
        real(dp) :: c, cont, ip, im, h
        integer :: nrow
        call record_text(.false., s, st)
        call write_text(SCR//'/rf.csv', s)
        call run_here('rf0', record_deck('rf.csv', 'record_columns = 1, 2, 3'), st, w)
        call t%check('record fd: runs', st%code == 0)
        if (st%code /= 0) return
        ! b (both ends of the cables at the support)
        h = 0.4_dp*1.0e-4_dp
        call budget_row(SCR//'/rf0.identify', 'b', c, cont, nrow)
        call run_here('rfbp', moved('b = 0.4', 'b = '//num(0.4_dp + h)), st, w)
        ip = kv('rfbp.identify', 'I1')
        call run_here('rfbm', moved('b = 0.4', 'b = '//num(0.4_dp - h)), st, w)
        im = kv('rfbm.identify', 'I1')
        write (*, '(a,es16.8,a,es16.8)') '   record dI1/db: budget ', c, ', whole fits ', &
            (ip - im)/(2*h)
        call t%check_close('record fd: dI1/db of the budget, a difference of whole fits', c, &
                           (ip - im)/(2*h), rtol=1.0e-4_dp)
        ! l alone (the rig asymmetric in the moved runs: the full model fits)
        h = 1.2_dp*1.0e-4_dp
        call budget_row(SCR//'/rf0.identify', 'l', c, cont, nrow)
        call run_here('rflp', moved('l = 1.2,', 'l = '//num(1.2_dp + h)//','), st, w)
        ip = kv('rflp.identify', 'I1')
        call run_here('rflm', moved('l = 1.2,', 'l = '//num(1.2_dp - h)//','), st, w)
        im = kv('rflm.identify', 'I1')
        write (*, '(a,es16.8,a,es16.8)') '   record dI1/dl: budget ', c, ', whole fits ', &
            (ip - im)/(2*h)
        call t%check_close('record fd: dI1/dl of the budget, a difference of whole fits', c, &
                           (ip - im)/(2*h), rtol=1.0e-4_dp)
    contains
        !> The record deck with `old` of its suspension line replaced by `new`.
        function moved(old, new) result(dk)
            character(len=*), intent(in) :: old, new
            character(len=:), allocatable :: dk, sus
            integer :: k
            sus = SUSP
            k = index(sus, old)
            sus = sus(1:k - 1)//new//sus(k + len(old):)
            dk = record_deck('rf.csv', 'record_columns = 1, 2, 3')
            k = index(dk, SUSP)
            dk = dk(1:k - 1)//sus//dk(k + len(SUSP):)
        end function moved
    end subroutine test_record_fd

    !> A table of three releases of periods (10, 30, 50 degrees, timing noise 1e-4 s, each
    !! release its own): the budget rows b and mass (common to every release, pooled with
    !! the releases' weights) against central differences of the whole table's run.
    subroutine test_table_fd(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        type(warning_t), allocatable :: w(:)
        character(len=:), allocatable :: tab
        type(rng_t) :: g
        real(dp) :: c, cont, ip, im, h
        integer :: r, i, nrow
        tab = 'trial,period,amplitude,u_period'//NL
        do r = 1, 3
            g = rng_stream(60 + r, 0)
            do i = 1, 5, 2
                tab = tab//itoa(r)//','//num(period_of(I1_TRUE, AMPS(i)) + &
                    1.0e-4_dp*rng_normal(g))//','//num(AMPS(i))//',1e-4'//NL
            end do
        end do
        call write_text(SCR//'/tf.csv', tab)
        call run_here('tf0', table_deck(SUSP, BODY), st, w)
        call t%check('table fd: runs', st%code == 0)
        if (st%code /= 0) return
        h = 0.4_dp*1.0e-5_dp
        call budget_row(SCR//'/tf0.identify', 'b', c, cont, nrow)
        call run_here('tfbp', table_deck(swap(SUSP, 'b = 0.4', 'b = '//num(0.4_dp + h)), &
                                         BODY), st, w)
        ip = kv('tfbp.identify', 'I1')
        call run_here('tfbm', table_deck(swap(SUSP, 'b = 0.4', 'b = '//num(0.4_dp - h)), &
                                         BODY), st, w)
        im = kv('tfbm.identify', 'I1')
        write (*, '(a,es16.8,a,es16.8)') '   table dI1/db: budget ', c, ', whole runs ', &
            (ip - im)/(2*h)
        call t%check_close('table fd: dI1/db of the budget, a difference of whole runs', c, &
                           (ip - im)/(2*h), rtol=1.0e-4_dp)
        h = 3.1_dp*1.0e-5_dp
        call budget_row(SCR//'/tf0.identify', 'mass', c, cont, nrow)
        call run_here('tfmp', table_deck(SUSP, swap(BODY, 'mass = 3.1', 'mass = '// &
                                                    num(3.1_dp + h))), st, w)
        ip = kv('tfmp.identify', 'I1')
        call run_here('tfmm', table_deck(SUSP, swap(BODY, 'mass = 3.1', 'mass = '// &
                                                    num(3.1_dp - h))), st, w)
        im = kv('tfmm.identify', 'I1')
        write (*, '(a,es16.8,a,es16.8)') '   table dI1/dmass: budget ', c, ', whole runs ', &
            (ip - im)/(2*h)
        call t%check_close('table fd: dI1/dmass of the budget, a difference of whole runs', &
                           c, (ip - im)/(2*h), rtol=1.0e-4_dp)
    contains
        function table_deck(sus, bod) result(s)
            character(len=*), intent(in) :: sus, bod
            character(len=:), allocatable :: s
            s = HEAD//sus//bod//"&measurement trials = 'tf.csv', u_mass = 0.001, "// &
                'u_b = 0.0005 /'//NL
        end function table_deck
        function swap(text, old, new) result(s)
            character(len=*), intent(in) :: text, old, new
            character(len=:), allocatable :: s
            integer :: k
            k = index(text, old)
            s = text(1:k - 1)//new//text(k + len(old):)
        end function swap
    end subroutine test_table_fd

    ! ------------------------------------------------------------------ tensors

    !> The test body's tensor: T_MOMENTS about the axes of the rotation of the quaternion
    !! (0.9, 0.3, -0.2, 0.25).
    function true_tensor() result(x)
        real(dp) :: x(6)
        real(dp) :: q(4), r(3, 3), jt(3, 3)
        integer :: k
        q = [0.9_dp, 0.3_dp, -0.2_dp, 0.25_dp]
        q = q/norm2(q)
        associate (a => q(1), b => q(2), c => q(3), e => q(4))
            r = reshape([a**2 + b**2 - c**2 - e**2, 2*(b*c + a*e), 2*(b*e - a*c), &
                         2*(b*c - a*e), a**2 - b**2 + c**2 - e**2, 2*(c*e + a*b), &
                         2*(b*e + a*c), 2*(c*e - a*b), a**2 - b**2 - c**2 + e**2], [3, 3])
        end associate
        jt = 0.0_dp
        do k = 1, 3
            jt = jt + T_MOMENTS(k)*spread(r(:, k), 2, 3)*spread(r(:, k), 1, 3)
        end do
        x = tensor_entries(jt)
    end function true_tensor

    !> Nine hangs (the three faces, the six edges of the body frame) of the tensor rig, each
    !! period timed with noise 1e-4 s (seed 3); `typo`: hang 7's period 3 ms long.
    function hangs_text(typo) result(tab)
        logical, intent(in) :: typo
        character(len=:), allocatable :: tab
        real(dp), parameter :: UP(3, 9) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 1, -1, &
            0, 1, 0, 1, 1, 0, -1, 0, 1, 1, 0, 1, -1], [3, 9])*1.0_dp
        type(hang_t) :: hg
        type(rig_t) :: rg
        type(accuracy_t) :: acc
        type(status_t) :: st
        type(rng_t) :: g
        real(dp) :: x(6), per, u(3), a(3)
        integer :: k
        x = true_tensor()
        acc%rtol = 1.0e-12_dp
        acc%atol = 1.0e-14_dp
        g = rng_stream(3, 0)
        tab = 'hang up_x up_y up_z along_x along_y along_z period'//NL
        do k = 1, 9
            u = UP(:, k)/norm2(UP(:, k))
            a = along_for(u)
            hg%id = k
            hg%line = k + 1
            hg%up = u
            hg%along = a
            hg%l = 1.2_dp
            hg%l_prime = 1.2_dp
            hg%b = 0.5_dp
            hg%b_prime = 0.4_dp
            hg%cg_depth = 0.1_dp
            hg%cg_offset = 0.0_dp
            call hang_rig(T_MASS, T_G, hg, x, rg, st)
            call hang_period(rg, acc, 0.0_dp, per, st)
            per = per + 1.0e-4_dp*rng_normal(g)
            if (typo .and. k == 7) per = per + 3.0e-3_dp
            tab = tab//itoa(k)//' '//num(u(1))//' '//num(u(2))//' '//num(u(3))//' '// &
                num(a(1))//' '//num(a(2))//' '//num(a(3))//' '//num(per)//NL
        end do
    end function hangs_text

    !> A tensor fit with u_period stated: consistent for clean hangs; with hang 7 mistyped
    !! inconsistent, one warning naming hang 7, its u inflated, and each true principal
    !! moment within U95; without u_period (the scatter sets it): not tested.
    subroutine test_tensor_check(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=512) :: line
        real(dp) :: m(3), um(3), uu(3), m0(3), u0(3)
        integer :: ex
        logical :: ok, l1, l2, l3, l4
        call tensor_run('tc_clean', hangs_text(.false.), ', u_period = 1e-4', ex)
        call t%check('tensor check: clean hangs run', ex == 0)
        l1 = file_has(SCR//'/tc_clean/tc_clean.tensor', 'fit_consistency = consistent')
        l2 = message_lines(SCR//'/tc_clean/stderr') == 0
        call t%check('tensor check: clean hangs are consistent', l1 .and. l2)
        call principal(SCR//'/tc_clean/tc_clean.tensor', m0, u0, uu, ok)
        call tensor_run('tc_typo', hangs_text(.true.), ', u_period = 1e-4', ex)
        call t%check('tensor check: a typo runs', ex == 0)
        l1 = file_has(SCR//'/tc_typo/tc_typo.tensor', 'fit_consistency = inconsistent')
        l2 = message_lines(SCR//'/tc_typo/stderr') == 1
        l3 = file_has(SCR//'/tc_typo/stderr', 'hang 7 (line 8)')
        l4 = file_has(SCR//'/tc_typo/stderr', 'inflated by the Birge ratio')
        call t%check('tensor check: a typo is inconsistent, one warning naming hang 7', &
                     l1 .and. l2 .and. l3 .and. l4)
        call principal(SCR//'/tc_typo/tc_typo.tensor', m, um, uu, ok)
        call read_kv_text(SCR//'/tc_typo/tc_typo.tensor', 'fit_birge_ratio', line)
        write (*, '(a,a,a,3es10.2,a,3es10.2)') '   a hang 30 u off: Birge ratio ', &
            trim(line), ', |I - truth| ', abs(m - T_MOMENTS), ', U95 ', uu
        call t%check('tensor check: with the typo its u inflated above the clean fit''s', &
                     ok .and. all(um > 2.0_dp*u0))
        call t%check('tensor check: with the typo each true moment within U95', &
                     ok .and. all(abs(m - T_MOMENTS) <= uu))
        call tensor_run('tc_nou', hangs_text(.false.), '', ex)
        l1 = file_has(SCR//'/tc_nou/tc_nou.tensor', 'fit_consistency = not tested')
        call t%check('tensor check: without u_period, not tested', ex == 0 .and. l1)
    contains
        subroutine tensor_run(name, tab, more, ex)
            character(len=*), intent(in) :: name, tab, more
            integer, intent(out) :: ex
            character(len=:), allocatable :: dd
            dd = SCR//'/'//name
            call fresh_dir(dd)
            call write_text(dd//'/hangs.txt', tab)
            call write_text(dd//'/'//name//'.nml', "&scene analyses = 'tensor' /"//NL// &
                            T_RIG//"&tensor hangs = 'hangs.txt'"//more//' /'//NL)
            ex = run(exe//' '//dd//'/'//name//'.nml --out '//dd, dd)
        end subroutine tensor_run
        subroutine principal(path, mm, u_m, u95, found)
            character(len=*), intent(in) :: path
            real(dp), intent(out) :: mm(3), u_m(3), u95(3)
            logical, intent(out) :: found
            character(len=512) :: v
            integer :: io
            found = .false.
            mm = 0.0_dp
            u_m = 0.0_dp
            u95 = 0.0_dp
            call read_kv_text(path, 'I_principal', v)
            read (v, *, iostat=io) mm
            if (io /= 0) return
            call read_kv_text(path, 'u_I_principal', v)
            read (v, *, iostat=io) u_m
            if (io /= 0) return
            call read_kv_text(path, 'U95_I_principal', v)
            read (v, *, iostat=io) u95
            found = io == 0
        end subroutine principal
    end subroutine test_tensor_check

end module test_selfcheck
