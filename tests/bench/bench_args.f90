!> What the benchmark programs share: an integer from the command line and a stop with the
!! message of a failed status (benchmarks are main programs' helpers: they may stop).
module bench_args
    use status, only: status_t
    implicit none
    private

    public :: int_arg, need

contains

    !> Command-line argument i as an integer (stops with a message when it is not one).
    integer function int_arg(i)
        integer, intent(in) :: i
        character(len=32) :: buf
        integer :: ios
        call get_command_argument(i, buf)
        read (buf, *, iostat=ios) int_arg
        if (ios /= 0) then
            write (*, '(a)') 'benchmark: argument '//trim(buf)//' is not an integer'
            stop 1
        end if
    end function int_arg

    !> Stop with "who: message" when s reports a failure.
    subroutine need(s, who)
        type(status_t), intent(in) :: s
        character(len=*), intent(in) :: who
        if (s%code /= 0) then
            write (*, '(a)') who//': '//s%msg
            stop 1
        end if
    end subroutine need

end module bench_args
