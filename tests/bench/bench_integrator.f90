!> Benchmark of module lsoda against the original Fortran LSODA (anchors).
!!
!! Usage: bench_integrator [OUT.dat [ANCHOR.csv]]
!!   OUT.dat     machine-readable results (default output/bench_integrator.dat)
!!   ANCHOR.csv  the original LSODA's figures (default
!!               ../shared/reference/integrator/fortran_lsoda.csv); when absent no ratios.
!!
!! For every problem of test_lsoda (rober, vdp1000, vdp1, arenstorf, hires, pendulum,
!! linear) and rtol = 1e-3 ... 1e-10 (atol rule and output grid of the anchors): steps,
!! rhs evaluations, Jacobian evaluations, method switches, scaled error at t_end
!! (max_i |y_i-ref_i|/(atol_i+rtol|ref_i|)) and CPU microseconds per solve (best of
!! 7 batches of ~0.07 s timed with cpu_time, after a 0.5 s warm-up), with the ratios to
!! the anchor.
program bench_integrator
    use kinds, only: dp
    use status, only: status_t, STATUS_OK
    use ode_system, only: ode_system_t, integrator_stats_t
    use test_lsoda, only: bench_problem, scaled_error, solve_on_grid, NBENCH, BENCH_NAMES
    implicit none

    integer, parameter :: NRTOL = 8, NBATCH = 7, MAXROWS = 200
    real(dp), parameter :: BATCH_SECONDS = 0.07_dp
    character(len=*), parameter :: HEADER = '# problem rtol steps rhs_evaluations '// &
        'jacobian_evaluations method_switches scaled_error cpu_us'

    ! anchor table
    character(len=16) :: a_name(MAXROWS)
    real(dp) :: a_rtol(MAXROWS), a_us(MAXROWS), a_err(MAXROWS)
    integer :: a_nfe(MAXROWS), na
    logical :: have_anchor

    character(len=512) :: outpath, csvpath, tmppath
    class(ode_system_t), allocatable :: sys
    real(dp), allocatable :: y0(:), grid(:), atol(:), yref(:), y(:)
    type(integrator_stats_t) :: st
    type(status_t) :: stat
    real(dp) :: rtol, err, us, r_nfe(NRTOL), r_err(NRTOL), r_us(NRTOL)
    integer :: ip, ir, u, ia, nr, worst
    integer :: sum_nfe, sum_anfe
    logical :: have_r(NRTOL)
    character(len=300) :: line, summary_lines(NBENCH)

    outpath = 'output/bench_integrator.dat'
    csvpath = '../shared/reference/integrator/fortran_lsoda.csv'
    if (command_argument_count() >= 1) call get_command_argument(1, outpath)
    if (command_argument_count() >= 2) call get_command_argument(2, csvpath)

    call read_anchor(trim(csvpath), have_anchor)
    if (.not. have_anchor) write (*, '(a)') 'anchor file '//trim(csvpath)// &
        ' not found: no ratios'

    tmppath = trim(outpath)//'.tmp'
    open (newunit=u, file=trim(tmppath), status='replace', action='write', iostat=ir)
    if (ir /= 0) then
        write (*, '(a)') 'cannot write '//trim(tmppath)
        stop 5
    end if
    write (u, '(a)') HEADER

    call warm_up()
    write (*, '(a)') 'problem    rtol     steps    nfe   nje sw  scaled_err     cpu_us'// &
        ' |  a_nfe   a_err     a_us | nfe/a err/a  us/a'
    do ip = 1, NBENCH
        have_r = .false.
        sum_nfe = 0
        sum_anfe = 0
        do ir = 1, NRTOL
            rtol = 10.0_dp**(-(ir + 2))
            call bench_problem(BENCH_NAMES(ip), rtol, sys, y0, grid, atol, yref, stat)
            if (allocated(y)) deallocate (y)
            allocate (y(size(y0)))
            call solve_on_grid(sys, y0, grid, rtol, atol, y, st, stat)
            if (stat%code /= STATUS_OK) then
                write (*, '(a)') trim(BENCH_NAMES(ip))//': solver failed: '//stat%msg
                err = huge(1.0_dp)
            else
                err = scaled_error(y, yref, rtol, atol)
            end if
            us = time_solve(sys, y0, grid, rtol, atol)
            write (u, '(a,1x,es7.1,4(1x,i0),1x,es11.5,1x,f0.3)') trim(BENCH_NAMES(ip)), rtol, &
                st%steps, st%rhs_evals, st%jac_evals, st%method_switches, err, us
            ia = find_anchor(BENCH_NAMES(ip), rtol)
            if (ia > 0) then
                have_r(ir) = .true.
                r_nfe(ir) = real(st%rhs_evals, dp)/a_nfe(ia)
                r_err(ir) = max(err, 1.0e-300_dp)/max(a_err(ia), 1.0e-300_dp)
                r_us(ir) = us/a_us(ia)
                sum_nfe = sum_nfe + st%rhs_evals
                sum_anfe = sum_anfe + a_nfe(ia)
                write (*, '(a9,es8.1,i8,i7,i6,i3,es12.3,f11.1,a,i7,es8.1,f9.1,a,3f6.2)') &
                    BENCH_NAMES(ip), rtol, st%steps, st%rhs_evals, st%jac_evals, &
                    st%method_switches, err, us, ' |', a_nfe(ia), a_err(ia), a_us(ia), ' |', &
                    r_nfe(ir), r_err(ir), r_us(ir)
            else
                write (*, '(a9,es8.1,i8,i7,i6,i3,es12.3,f11.1)') BENCH_NAMES(ip), rtol, &
                    st%steps, st%rhs_evals, st%jac_evals, st%method_switches, err, us
            end if
        end do
        call summarise(ip)
    end do
    call print_summary()
    close (u)
    call execute_command_line('mv -f '//trim(tmppath)//' '//trim(outpath), exitstat=ir)
    if (ir /= 0) then
        write (*, '(a)') 'cannot rename '//trim(tmppath)//' to '//trim(outpath)
        stop 5
    end if
    write (*, '(a)') 'results written to '//trim(outpath)

contains

    !> Keep the CPU busy ~0.5 s before timing (clock ramp-up, caches).
    subroutine warm_up()
        real(dp) :: c0, c1
        real(dp), allocatable :: yw(:)
        call bench_problem('vdp1000', 1.0e-6_dp, sys, y0, grid, atol, yref, stat)
        allocate (yw(size(y0)))
        call cpu_time(c0)
        do
            call solve_on_grid(sys, y0, grid, 1.0e-6_dp, atol, yw, st, stat)
            call cpu_time(c1)
            if (c1 - c0 > 0.5_dp) exit
        end do
    end subroutine warm_up

    !> Per-problem summary line: geometric means of the ratios, whole-sweep nfe ratio and
    !! the worst rows.
    subroutine summarise(ip)
        integer, intent(in) :: ip
        nr = count(have_r)
        if (nr == 0) then
            summary_lines(ip) = trim(BENCH_NAMES(ip))//': no anchor rows'
            return
        end if
        worst = maxloc(r_nfe, 1, mask=have_r)
        write (line, '(a9,a,3f6.2,a,f6.2,a,es8.1,a,f5.2,a,es8.1,a,f6.2,a,es8.1,a,f5.2)') &
            BENCH_NAMES(ip), ' geo-mean nfe/err/us', &
            geomean(r_nfe), geomean(r_err), geomean(r_us), &
            ' | sweep nfe', real(sum_nfe, dp)/max(sum_anfe, 1), &
            ' | worst nfe @', 10.0_dp**(-(worst + 2)), ' ', r_nfe(worst), &
            ' err @', 10.0_dp**(-(maxloc(r_err, 1, mask=have_r) + 2)), ' ', &
            maxval(r_err, mask=have_r), ' us @', &
            10.0_dp**(-(maxloc(r_us, 1, mask=have_r) + 2)), ' ', maxval(r_us, mask=have_r)
        summary_lines(ip) = trim(line)
    end subroutine summarise

    real(dp) function geomean(r)
        real(dp), intent(in) :: r(:)
        geomean = exp(sum(log(r), mask=have_r)/count(have_r))
    end function geomean

    subroutine print_summary()
        integer :: k
        write (*, '(/,a)') 'summary (ratios ours/anchor; geometric means over rtol; '// &
            'sweep nfe = total nfe ratio)'
        do k = 1, NBENCH
            write (*, '(a)') trim(summary_lines(k))
        end do
    end subroutine print_summary

    !> Best-of-NBATCH CPU microseconds per solve.
    real(dp) function time_solve(sys, y0, grid, rtol, atol) result(best)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: y0(:), grid(:), atol(:)
        real(dp), intent(in) :: rtol
        real(dp) :: t0, t1, yy(size(y0))
        type(integrator_stats_t) :: s2
        type(status_t) :: st2
        integer :: reps, b, k
        ! calibrate the batch size
        reps = 1
        do
            call cpu_time(t0)
            do k = 1, reps
                call solve_on_grid(sys, y0, grid, rtol, atol, yy, s2, st2)
            end do
            call cpu_time(t1)
            if (t1 - t0 >= 0.2_dp*BATCH_SECONDS .or. reps > 1000000) exit
            reps = reps*4
        end do
        reps = max(1, nint(reps*BATCH_SECONDS/max(t1 - t0, 1.0e-6_dp)))
        best = huge(1.0_dp)
        do b = 1, NBATCH
            call cpu_time(t0)
            do k = 1, reps
                call solve_on_grid(sys, y0, grid, rtol, atol, yy, s2, st2)
            end do
            call cpu_time(t1)
            best = min(best, (t1 - t0)/reps*1.0e6_dp)
        end do
    end function time_solve

    !> Row of the anchor table for (name, rtol), 0 when none.
    integer function find_anchor(name, rtol)
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: rtol
        integer :: k
        find_anchor = 0
        if (.not. have_anchor) return
        do k = 1, na
            if (trim(a_name(k)) == trim(name) .and. abs(a_rtol(k)/rtol - 1.0_dp) < 1.0e-6_dp) then
                find_anchor = k
                return
            end if
        end do
    end function find_anchor

    !> Read problem, rtol, nfe, us_solve and y_end (-> scaled error) from the anchor CSV.
    subroutine read_anchor(path, ok)
        character(len=*), intent(in) :: path
        logical, intent(out) :: ok
        character(len=2000) :: rec
        character(len=400) :: fields(13)
        integer :: v, ios, nf, p0, k
        real(dp), allocatable :: yend(:)
        class(ode_system_t), allocatable :: s
        real(dp), allocatable :: q0(:), g(:), at(:), yr(:)
        type(status_t) :: pst
        ok = .false.
        na = 0
        open (newunit=v, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        read (v, '(a)', iostat=ios) rec      ! header
        do
            read (v, '(a)', iostat=ios) rec
            if (ios /= 0) exit
            if (len_trim(rec) == 0) cycle
            ! split into 13 comma-separated fields
            nf = 0
            p0 = 1
            do k = 1, len_trim(rec)
                if (rec(k:k) == ',' .and. nf < 12) then
                    nf = nf + 1
                    fields(nf) = rec(p0:k - 1)
                    p0 = k + 1
                end if
            end do
            nf = nf + 1
            fields(nf) = rec(p0:len_trim(rec))
            if (nf /= 13 .or. na >= MAXROWS) cycle
            na = na + 1
            a_name(na) = trim(adjustl(fields(1)(1:16)))
            read (fields(2), *, iostat=ios) a_rtol(na)
            if (ios == 0) read (fields(4), *, iostat=ios) a_nfe(na)
            if (ios == 0) read (fields(10), *, iostat=ios) a_us(na)
            if (ios /= 0) then
                na = na - 1
                cycle
            end if
            call bench_problem(trim(a_name(na)), a_rtol(na), s, q0, g, at, yr, pst)
            a_err(na) = -1.0_dp
            if (pst%code == STATUS_OK) then
                if (allocated(yend)) deallocate (yend)
                allocate (yend(size(q0)))
                read (fields(13), *, iostat=ios) yend
                if (ios == 0) a_err(na) = scaled_error(yend, yr, a_rtol(na), at)
            end if
        end do
        close (v)
        ok = na > 0
    end subroutine read_anchor

end program bench_integrator
