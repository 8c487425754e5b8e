!> bifilar: dynamics of the bifilar pendulum (Kane & Tseng 1966), driven by namelist decks.
!!
!! Usage:  bifilar DECK.nml [--out DIR]
!!         bifilar --report [DIR]   (DIR/report.md from the paper scenes' output in DIR)
!! Runs the analyses the deck's &scene asks for and writes DIR/NAME.* (DIR defaults to
!! `output`).  Exit status: 0 success, 1 usage, 2 bad deck, 3 numerical failure,
!! 4 the model no longer holds (e.g. a cable goes slack), 5 output cannot be written.
program bifilar
    use, intrinsic :: iso_fortran_env, only: error_unit
    use kinds, only: dp
    use status, only: status_t, ERR_DECK, ERR_MODEL, ERR_IO
    use deck, only: deck_t, read_deck, analysis_requested
    use simulate, only: run_simulation, run_summary_t
    use paper_claims, only: write_report
    use stability, only: run_floquet, run_chart
    use floquet, only: floquet_result_t
    use work_precision, only: run_work_precision, wp_result_t
    implicit none
    type(deck_t) :: d
    type(status_t) :: stat
    type(run_summary_t) :: sm
    type(floquet_result_t) :: fr
    type(wp_result_t) :: wp
    integer :: nstable
    real(dp) :: secs
    character(len=:), allocatable :: deck_path, outdir
    character(len=1024) :: arg
    integer :: i, nargs

    nargs = command_argument_count()
    outdir = 'output'
    deck_path = ''
    i = 1
    do while (i <= nargs)
        call get_command_argument(i, arg)
        if (trim(arg) == '--report') then
            if (i < nargs) call get_command_argument(i + 1, arg)
            if (i == nargs) arg = 'output'
            call write_report(trim(arg), stat)
            if (stat%code /= 0) call fail(stat)
            write (*, '(a)') 'wrote '//trim(arg)//'/report.md'
            stop
        else if (trim(arg) == '--out' .and. i < nargs) then
            call get_command_argument(i + 1, arg)
            outdir = trim(arg)
            i = i + 2
            cycle
        else if (arg(1:1) == '-') then
            call usage('unknown option '//trim(arg))
        else if (len(deck_path) > 0) then
            call usage('only one deck per run')
        end if
        deck_path = trim(arg)
        i = i + 1
    end do
    if (len(deck_path) == 0) call usage('no deck given')

    call read_deck(deck_path, d, stat)
    if (stat%code /= 0) call fail(stat)

    if (analysis_requested(d, 'work_precision')) then
        call run_work_precision(d, outdir, wp, stat)
        if (stat%code /= 0) call fail(stat)
        if (trim(d%model) == 'elastic') then
            write (*, '(a)') d%name//': work_precision: wrote '//outdir//'/'//d%name// &
                '.wp.dat, .wp_rk4.dat and .wp_radau.dat (LSODA''s curve below)'
        else
            write (*, '(a)') d%name//': work_precision: wrote '//outdir//'/'//d%name// &
                '.wp.dat and .wp_rk4.dat'
        end if
        write (*, '(a10,a12,a10,a12,a12)') 'rtol', 'cpu s', 'rhs', 'err theta', 'err Q'
        do i = 1, size(wp%lsoda)
            if (wp%lsoda(i)%ok) write (*, '(es10.1,es12.3,i10,2es12.3)') wp%lsoda(i)%rtol, &
                wp%lsoda(i)%cpu_seconds, wp%lsoda(i)%rhs_evaluations, wp%lsoda(i)%error_theta, &
                wp%lsoda(i)%error_q
        end do
    end if
    if (analysis_requested(d, 'floquet')) then
        call run_floquet(d, outdir, fr, stat)
        if (stat%code /= 0) call fail(stat)
        write (*, '(a,a,f0.6,a,es12.5,a,a)') d%name, ': floquet period ', fr%period, &
            ', max modulus ', fr%max_modulus, ', stable ', merge('yes', 'no ', fr%stable)
    end if
    if (analysis_requested(d, 'chart')) then
        call run_chart(d, outdir, nstable, secs, stat)
        if (stat%code /= 0) call fail(stat)
        write (*, '(a,a,i0,a,i0,a,f0.2,a)') d%name, ': chart ', d%chart_nx*d%chart_ny, &
            ' points, ', nstable, ' stable, ', secs, ' s'
    end if
    if (analysis_requested(d, 'simulate')) then
        call run_simulation(d, outdir, sm, stat)
        if (stat%code /= 0) call fail(stat)
        write (*, '(a,a,f0.4,a,i0,a,i0,a,es9.2,a,es9.2)') d%name, ': cpu ', sm%cpu_seconds, &
            ' s, steps ', sm%steps, ', rhs ', sm%rhs_evaluations, ', max |dE| ', &
            sm%max_abs_energy_error, ', max |residual| ', sm%max_abs_constraint_residual
    end if
    ! main-program variables are never freed by the run-time library: free them (valgrind)
    deallocate (deck_path, outdir)

contains

    subroutine usage(msg)
        character(len=*), intent(in) :: msg
        write (error_unit, '(a)') 'bifilar: '//msg
        write (error_unit, '(a)') 'usage: bifilar DECK.nml [--out DIR] | bifilar --report [DIR]'
        error stop 1
    end subroutine usage

    subroutine fail(st)
        type(status_t), intent(in) :: st
        character(len=24) :: kind      ! fixed length: error stop frees nothing (valgrind)
        select case (st%code)
        case (ERR_DECK)
            kind = 'bad input'
        case (ERR_MODEL)
            kind = 'model no longer valid'
        case (ERR_IO)
            kind = 'cannot write output'
        case default
            kind = 'numerical failure'
        end select
        write (error_unit, '(a)') 'bifilar: error ('//trim(kind)//'): '//st%msg
        select case (st%code)
        case (ERR_DECK)
            error stop 2
        case (ERR_MODEL)
            error stop 4
        case (ERR_IO)
            error stop 5
        case default
            error stop 3
        end select
    end subroutine fail

end program bifilar
