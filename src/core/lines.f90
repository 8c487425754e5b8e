!> Whole lines from a text file, of any length, read in time linear in their length.
module lines
    implicit none
    private

    public :: read_line

    !> Longest line a reader accepts by default (characters): decks and records refuse longer.
    integer, parameter, public :: LINE_MAX = 4096

contains

    !> Read one whole line of any length (tabs and carriage returns as blanks), in time linear
    !! in its length; reading stops after max_len + 1 characters (default LINE_MAX; the
    !! caller refuses such a line), so a file without newlines (/dev/zero) ends at once.
    subroutine read_line(u, line, ios, msg, max_len)
        integer, intent(in) :: u                    !! open unit
        character(len=:), allocatable, intent(out) :: line   !! the line, without newline
        integer, intent(out) :: ios                 !! 0, < 0 at end of file, > 0 on error
        character(len=*), intent(inout) :: msg      !! message for ios > 0
        integer, intent(in), optional :: max_len    !! longest line the caller accepts
        character(len=1024) :: chunk
        character(len=:), allocatable :: buf, grown
        integer :: n, nl, nmax
        nmax = LINE_MAX
        if (present(max_len)) nmax = max_len
        allocate (character(len=1024) :: buf)
        nl = 0
        do
            n = 0
            read (u, '(a)', advance='no', size=n, iostat=ios, iomsg=msg) chunk
            if (nl + n > len(buf)) then
                allocate (character(len=2*(nl + n)) :: grown)
                grown(1:nl) = buf(1:nl)
                call move_alloc(grown, buf)
            end if
            buf(nl + 1:nl + n) = chunk(1:n)
            nl = nl + n
            if (is_iostat_eor(ios)) then
                ios = 0
                exit
            end if
            if (is_iostat_end(ios) .and. nl > 0) then
                ios = 0
                exit
            end if
            if (ios /= 0) exit
            if (nl > nmax) exit
        end do
        line = buf(1:nl)
        do n = 1, nl
            if (line(n:n) == achar(9) .or. line(n:n) == achar(13)) line(n:n) = ' '
        end do
    end subroutine read_line

end module lines
