!> sweep_probe: the sweep engine over MPI ranks with a task of known values (module
!! probe_task), for the tests (suite sweep; built as $(BIN)/sweep_probe_mpi by the MPI
!! build, run under mpirun).
!!
!!   mpirun -np N sweep_probe_mpi MODE NPOINTS FINGERPRINT_FILE [CHECKPOINT [NAP]]
!!
!! MODE as in probe_task (ok, fail_worker, fail_rank0); FINGERPRINT_FILE stands for the
!! deck; NAP (optional, default 1000): microseconds of sleep per unit of a point's cost
!! (0: points cost nothing but the engine's own work).  Rank 0 prints one line:
!! `ok POINTS BAD RANK0_POINTS OTHER_POINTS WALL_S REQUESTS SERVE_S` (BAD: points whose
!! first two values are wrong; REQUESTS and SERVE_S: requests rank 0 answered and its time
!! taking messages) or `error CODE: MESSAGE`; exit status 0 or 3.
program sweep_probe
    use, intrinsic :: iso_c_binding, only: c_int
    use kinds, only: dp
    use status, only: status_t, STATUS_OK
    use sweep_engine, only: sweep_run, sweep_start, sweep_finish, sweep_is_master, &
        sweep_next_job, sweep_serve, sweep_job_t, sweep_options_t, sweep_report_t
    use probe_task, only: probe_task_t
    implicit none
    interface
        subroutine c_exit(status) bind(C, name='exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit
    end interface
    type(probe_task_t) :: task
    type(status_t) :: stat
    type(sweep_job_t) :: job
    type(sweep_options_t) :: opt
    type(sweep_report_t) :: rep
    real(dp), allocatable :: v(:, :)
    character(len=256) :: arg, fp, ckpt
    integer :: i, bad, code, n0
    logical :: quit

    call sweep_start(stat)
    call get_command_argument(1, arg)
    task%mode = arg(1:len(task%mode))
    call get_command_argument(2, arg)
    read (arg, *) task%n
    call get_command_argument(3, fp)
    ckpt = ''
    if (command_argument_count() >= 4) call get_command_argument(4, ckpt)
    if (command_argument_count() >= 5) then
        call get_command_argument(5, arg)
        read (arg, *) task%nap
    end if
    if (.not. sweep_is_master()) then
        do
            call sweep_next_job(job, quit)
            if (quit) exit
            call sweep_serve(job, stat, task)
        end do
        call sweep_finish()
        call c_exit(0_c_int)
    end if
    task%rank0 = 1
    opt%checkpoint_seconds = 0.0_dp
    call sweep_run(task, 'probe', trim(fp), trim(ckpt), '', task%n, 4, v, stat, opt, rep)
    code = 0
    if (stat%code /= STATUS_OK) then
        write (*, '(a,i0,a)') 'error ', stat%code, ': '//stat%msg
        code = 3
    else
        bad = 0
        n0 = 0
        do i = 1, task%n
            if (v(1, i) /= real(i, dp) .or. v(2, i) /= sqrt(real(i, dp))) bad = bad + 1
            if (nint(v(3, i)) == 1) n0 = n0 + 1
        end do
        write (*, '(a,i0,1x,i0,1x,i0,1x,i0,1x,f0.4,1x,i0,1x,f0.4)') 'ok ', task%n, bad, n0, &
            task%n - n0, rep%wall_seconds, rep%requests, rep%serve_seconds
    end if
    flush (6)
    call sweep_finish()
    call c_exit(int(code, c_int))
end program sweep_probe
