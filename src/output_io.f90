!> Output helpers: atomic files (written to PATH.tmp, renamed to PATH on commit, so nothing
!! partial is ever left behind) and `key = value` lines for summary files.
module output_io
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_IO
    implicit none
    private

    public :: atomic_open, atomic_commit, atomic_abort, write_kv, read_kv, all_finite

    !> Write `key = value` on one line; reals in full precision, logicals as yes/no.
    interface write_kv
        module procedure write_kv_real, write_kv_int, write_kv_char, write_kv_logical
    end interface write_kv

    interface
        !> C library rename(2): atomic within one file system.
        integer(c_int) function c_rename(old, new) bind(C, name='rename')
            import :: c_int, c_char
            character(kind=c_char), dimension(*), intent(in) :: old    !! null-terminated
            character(kind=c_char), dimension(*), intent(in) :: new    !! null-terminated
        end function c_rename
    end interface

contains

    !> Open PATH.tmp for formatted sequential writing (replacing any old one).
    subroutine atomic_open(path, unit, stat)
        character(len=*), intent(in) :: path        !! final file name
        integer, intent(out) :: unit                !! unit to write to
        type(status_t), intent(out) :: stat         !! ERR_IO when PATH.tmp cannot be opened
        integer :: ios
        character(len=512) :: msg
        stat%code = STATUS_OK
        msg = ''
        unit = -1
        open (newunit=unit, file=path//'.tmp', status='replace', action='write', &
              form='formatted', access='sequential', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            unit = -1
            call set_error(stat, ERR_IO, 'cannot open '//path//'.tmp for writing: '//trim(msg))
        end if
    end subroutine atomic_open

    !> Close unit and rename PATH.tmp to PATH.
    subroutine atomic_commit(unit, path, stat)
        integer, intent(in) :: unit                 !! unit from atomic_open
        character(len=*), intent(in) :: path        !! final file name (as given to atomic_open)
        type(status_t), intent(out) :: stat         !! ERR_IO when closing or renaming fails
        integer :: ios
        integer(c_int) :: rc
        character(len=512) :: msg
        stat%code = STATUS_OK
        msg = ''
        close (unit, iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_IO, 'cannot close '//path//'.tmp: '//trim(msg))
            return
        end if
        rc = c_rename(path//'.tmp'//c_null_char, path//c_null_char)
        if (rc /= 0) then
            call set_error(stat, ERR_IO, 'cannot rename '//path//'.tmp to '//path)
        end if
    end subroutine atomic_commit

    !> Give up an atomic file: close the unit deleting PATH.tmp; PATH is left untouched.
    subroutine atomic_abort(unit, path)
        integer, intent(in) :: unit                 !! unit from atomic_open
        character(len=*), intent(in) :: path        !! final file name (as given to atomic_open)
        logical :: opened, exists
        integer :: ios, u
        opened = .false.
        if (unit /= -1) inquire (unit=unit, opened=opened, iostat=ios)
        if (opened) then
            close (unit, status='delete', iostat=ios)
        end if
        ! Whatever happened to the unit, no PATH.tmp may be left behind.
        inquire (file=path//'.tmp', exist=exists, iostat=ios)
        if (ios == 0 .and. exists) then
            open (newunit=u, file=path//'.tmp', status='old', iostat=ios)
            if (ios == 0) close (u, status='delete', iostat=ios)
        end if
    end subroutine atomic_abort

    !> `key = value` for a real, in full precision (17 significant digits).
    subroutine write_kv_real(unit, key, value)
        integer, intent(in) :: unit                 !! open formatted unit
        character(len=*), intent(in) :: key         !! key
        real(dp), intent(in) :: value               !! value
        character(len=32) :: buf
        write (buf, '(es25.16e3)') value
        write (unit, '(a)') key//' = '//trim(adjustl(buf))
    end subroutine write_kv_real

    !> `key = value` for an integer.
    subroutine write_kv_int(unit, key, value)
        integer, intent(in) :: unit                 !! open formatted unit
        character(len=*), intent(in) :: key         !! key
        integer, intent(in) :: value                !! value
        write (unit, '(a,i0)') key//' = ', value
    end subroutine write_kv_int

    !> `key = value` for a character string (trailing blanks dropped).
    subroutine write_kv_char(unit, key, value)
        integer, intent(in) :: unit                 !! open formatted unit
        character(len=*), intent(in) :: key         !! key
        character(len=*), intent(in) :: value       !! value
        write (unit, '(a)') key//' = '//trim(value)
    end subroutine write_kv_char

    !> `key = yes` or `key = no`.
    subroutine write_kv_logical(unit, key, value)
        integer, intent(in) :: unit                 !! open formatted unit
        character(len=*), intent(in) :: key         !! key
        logical, intent(in) :: value                !! value
        if (value) then
            write (unit, '(a)') key//' = yes'
        else
            write (unit, '(a)') key//' = no'
        end if
    end subroutine write_kv_logical

    !> True when every element of x is finite (no NaN, no Inf).
    pure logical function all_finite(x)
        real(dp), intent(in) :: x(:)                !! values to test
        all_finite = all(ieee_is_finite(x))
    end function all_finite

    !> The real value of `key = value` in a file (lines starting with # are skipped);
    !! found = .false. when the file or the key is absent or the value is not a number.
    subroutine read_kv(path, key, val, found)
        character(len=*), intent(in) :: path    !! file of key = value lines
        character(len=*), intent(in) :: key     !! the key
        real(dp), intent(out) :: val            !! its value (0 when not found)
        logical, intent(out) :: found
        integer :: u, ios, eq
        character(len=512) :: line
        val = 0.0_dp
        found = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            eq = index(line, '=')
            if (eq == 0 .or. line(1:1) == '#') cycle
            if (trim(adjustl(line(1:eq - 1))) /= key) cycle
            read (line(eq + 1:), *, iostat=ios) val
            found = ios == 0
            exit
        end do
        close (u)
    end subroutine read_kv

end module output_io
