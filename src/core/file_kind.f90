!> What a path names, found without blocking, before a reader opens it (a FIFO
!! given as a record or a deck blocked the program for ever in `open`, waiting for a
!! writer).
!!
!! * A folder: `path/.` exists.
!! * Otherwise the path is opened with O_RDONLY | O_NONBLOCK | O_NOCTTY (C's open(2); a
!!   FIFO opened so returns at once) and sought to its end (lseek(2)):
!!   - it cannot be opened: FILE_MISSING (missing, no permission, a socket);
!!   - it cannot be sought: FILE_STREAM (a FIFO, a terminal, a pipe);
!!   - its end is at 0 but a byte can be read: FILE_DEVICE (/dev/zero, /dev/urandom,
!!     /proc files: no size, endless or changing);
!!   - else FILE_REGULAR (a regular file, a symbolic link to one, /dev/null).
!! The flag values are Linux's (O_NONBLOCK = 0o4000, O_NOCTTY = 0o400 on x86-64, ARM and
!! RISC-V).  No module state: every call asks afresh.
module file_kind
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_long, c_size_t, c_null_char, &
        c_ptr, c_loc
    implicit none
    private

    public :: kind_of_file, kind_name

    integer, parameter, public :: FILE_REGULAR = 0, FILE_FOLDER = 1, FILE_STREAM = 2, &
        FILE_DEVICE = 3, FILE_MISSING = 4

    integer(c_int), parameter :: O_RDONLY = 0, O_NONBLOCK = 2048, O_NOCTTY = 256
    integer(c_int), parameter :: SEEK_END = 2

    interface
        integer(c_int) function c_open(path, flags) bind(C, name='open')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), value :: flags
        end function c_open
        integer(c_long) function c_lseek(fd, offset, whence) bind(C, name='lseek')
            import :: c_int, c_long
            integer(c_int), value :: fd
            integer(c_long), value :: offset
            integer(c_int), value :: whence
        end function c_lseek
        integer(c_long) function c_read(fd, buf, n) bind(C, name='read')
            import :: c_int, c_long, c_size_t, c_ptr
            integer(c_int), value :: fd
            type(c_ptr), value :: buf
            integer(c_size_t), value :: n
        end function c_read
        integer(c_int) function c_close(fd) bind(C, name='close')
            import :: c_int
            integer(c_int), value :: fd
        end function c_close
    end interface

contains

    !> The kind of file at path: FILE_REGULAR, FILE_FOLDER, FILE_STREAM, FILE_DEVICE or
    !! FILE_MISSING (see the module header).  Never blocks.
    function kind_of_file(path) result(k)
        character(len=*), intent(in) :: path        !! the path as given
        integer :: k
        logical :: is_dir
        integer(c_int) :: fd, rc
        integer(c_long) :: pos, got
        character(kind=c_char), target :: byte(1)
        k = FILE_MISSING
        if (len_trim(path) == 0) return
        inquire (file=path//'/.', exist=is_dir)
        if (is_dir) then
            k = FILE_FOLDER
            return
        end if
        fd = c_open(path//c_null_char, ior(O_RDONLY, ior(O_NONBLOCK, O_NOCTTY)))
        if (fd < 0) return
        pos = c_lseek(fd, 0_c_long, SEEK_END)
        if (pos < 0) then
            k = FILE_STREAM
        else if (pos == 0) then
            got = c_read(fd, c_loc(byte), 1_c_size_t)
            k = merge(FILE_DEVICE, FILE_REGULAR, got > 0)
        else
            k = FILE_REGULAR
        end if
        rc = c_close(fd)
    end function kind_of_file

    !> What a kind of file is, for messages: 'a folder', 'a FIFO, pipe or terminal', ...
    pure function kind_name(k) result(s)
        integer, intent(in) :: k                    !! a FILE_* value
        character(len=48) :: s
        select case (k)
        case (FILE_REGULAR)
            s = 'a regular file'
        case (FILE_FOLDER)
            s = 'a folder'
        case (FILE_STREAM)
            s = 'a FIFO, a pipe or a terminal'
        case (FILE_DEVICE)
            s = 'a device or a file without a size'
        case default
            s = 'missing or unreadable'
        end select
    end function kind_name

end module file_kind
