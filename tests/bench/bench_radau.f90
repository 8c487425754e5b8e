!> Benchmark of module radau on the seven standard problems of the anchors
!! (shared/reference/integrator: Robertson, Van der Pol mu = 1000 and 1, Arenstorf, HIRES,
!! pendulum, stiff linear; their atol rules, grids and references), rtol = 1e-3 ... 1e-10:
!! Radau IIA's steps, right-hand sides (finite-difference Jacobians included), Jacobians,
!! LU factorisations, rejected steps, scaled error at t_end (max_i |y_i - ref_i|/(atol_i +
!! rtol |ref_i|)) and CPU microseconds per solve (best of 3 batches of >= 0.05 s), beside
!! our LSODA's steps, right-hand sides and scaled error (equal to the original LSODA's:
!! bench_integrator).
!!
!! Usage: bench_radau [OUT.dat] (default output/bench_radau.dat).
program bench_radau
    use kinds, only: dp
    use status, only: status_t, STATUS_OK
    use ode_system, only: ode_system_t, integrator_stats_t
    use test_lsoda, only: bench_problem, scaled_error, solve_on_grid, NBENCH, BENCH_NAMES
    use test_radau, only: radau_on_grid
    use output_io, only: atomic_open, atomic_commit
    implicit none
    integer, parameter :: NRTOL = 8
    class(ode_system_t), allocatable :: sys
    real(dp), allocatable :: y0(:), grid(:), atol(:), yref(:), y(:)
    type(integrator_stats_t) :: rs
    type(integrator_stats_t) :: ls
    type(status_t) :: stat
    real(dp) :: rtol, err_r, err_l, us
    integer :: ip, ir, u
    character(len=1024) :: outpath
    outpath = 'output/bench_radau.dat'
    if (command_argument_count() >= 1) call get_command_argument(1, outpath)
    call atomic_open(trim(outpath), u, stat)
    if (stat%code /= STATUS_OK) error stop 'bench_radau: cannot write the result file'
    write (u, '(a)') '# problem rtol steps rhs_evaluations jacobian_evaluations lu_decomps '// &
        'rejected scaled_error cpu_us lsoda_steps lsoda_rhs_evaluations lsoda_scaled_error'
    write (*, '(a)') 'Radau IIA on the standard problems (our LSODA = the original''s counts '// &
        'beside it)'
    write (*, '(a9,a8,a7,a7,a6,a6,a5,a11,a10,a3,a8,a7,a11)') 'problem', 'rtol', 'steps', 'rhs', &
        'jac', 'lu', 'rej', 'scaled err', 'cpu us', '|', 'steps', 'rhs', 'scaled err'
    do ip = 1, NBENCH
        do ir = 1, NRTOL
            rtol = 10.0_dp**(-(ir + 2))
            call bench_problem(BENCH_NAMES(ip), rtol, sys, y0, grid, atol, yref, stat)
            if (allocated(y)) deallocate (y)
            allocate (y(size(y0)))
            call radau_on_grid(sys, y0, grid, rtol, atol, y, rs, stat)
            err_r = huge(1.0_dp)
            if (stat%code == STATUS_OK) err_r = scaled_error(y, yref, rtol, atol)
            us = time_radau(sys, y0, grid, rtol, atol)
            call solve_on_grid(sys, y0, grid, rtol, atol, y, ls, stat)
            err_l = huge(1.0_dp)
            if (stat%code == STATUS_OK) err_l = scaled_error(y, yref, rtol, atol)
            write (*, '(a9,es8.1,i7,i7,i6,i6,i5,es11.2,f10.1,a3,i8,i7,es11.2)') &
                BENCH_NAMES(ip), rtol, rs%steps, rs%rhs_evals, rs%jac_evals, rs%lu_decomps, &
                rs%error_test_failures, err_r, us, '|', ls%steps, ls%rhs_evals, err_l
            write (u, '(a,1x,es7.1,5(1x,i0),1x,es11.4,1x,f0.2,2(1x,i0),1x,es11.4)') &
                trim(BENCH_NAMES(ip)), rtol, rs%steps, rs%rhs_evals, rs%jac_evals, &
                rs%lu_decomps, rs%error_test_failures, err_r, us, ls%steps, ls%rhs_evals, err_l
        end do
    end do
    call atomic_commit(u, trim(outpath), stat)
    if (stat%code /= STATUS_OK) error stop 'bench_radau: cannot write the result file'
    write (*, '(a)') 'results written to '//trim(outpath)

contains

    !> CPU microseconds per Radau solve: best of 3 batches of at least 0.05 s.
    real(dp) function time_radau(sys, y0, grid, rtol, atol) result(best)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: y0(:), grid(:), rtol, atol(:)
        real(dp) :: t0, t1, yy(size(y0))
        type(integrator_stats_t) :: s2
        type(status_t) :: st2
        integer :: b, n
        best = huge(1.0_dp)
        do b = 1, 3
            n = 0
            call cpu_time(t0)
            do
                call radau_on_grid(sys, y0, grid, rtol, atol, yy, s2, st2)
                n = n + 1
                call cpu_time(t1)
                if (t1 - t0 >= 0.05_dp) exit
            end do
            best = min(best, (t1 - t0)/n*1.0e6_dp)
        end do
    end function time_radau

end program bench_radau
