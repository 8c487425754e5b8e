!> How output files come to exist: every file is written under a temporary name unique to
!! the process, `PATH.tmp.PID.N`, checked, and renamed to PATH only when complete, so no
!! partial, stale-mixed or corrupt file is ever left behind.
!!
!! - `atomic_open` / `atomic_commit` / `atomic_abort`: one file on its own.
!! - `out_files_t`: the files of one run (one deck).  Each file is opened with `%open`, and
!!   when written, checked and closed with `%close` (it then waits under its temporary
!!   name); `%commit` renames them all together at the end of the run, under an exclusive
!!   lock on the output folder (flock(2); bifilar processes writing into the same folder
!!   commit one after the other, so a run's .dat and .summary belong together), and on any
!!   failure removes every file of the run, committed ones included; `%discard` removes
!!   them all when the run fails.
!!
!! Checking a file: the writer passes the iostat of its writes (a write with iostat= stops
!! nothing; `if (ios == 0) write (u, ..., iostat=ios)` keeps the first failure), the unit is
!! flushed and closed with iostat, and the size of the file on disk must equal the number
!! of bytes the run-time library says it wrote: gfortran 12 reports no error at all when
!! the disk is full (the writes, the flush and the close all return iostat = 0 and the file
!! is cut short), and the size check is what catches it.  Failures are ERR_IO.
!!
!! `make_dir` creates a folder and its parents (mkdir -p) and checks that it can be written;
!! a name the system cannot take (longer than PATH_MAX, or a part longer than NAME_MAX) is
!! refused before anything is created, and a failure removes the folders it made.
!!
!! Signals: every temporary file is registered with module signals from just before it is
!! created until it is renamed or removed, so that SIGINT, SIGTERM or SIGHUP at any moment
!! removes it (only SIGKILL can leave one).
module output_io
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_null_ptr, &
        c_associated
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_IO
    use text, only: itoa
    use signals, only: signals_track, signals_untrack, signals_created
    use file_kind, only: kind_of_file, kind_name, FILE_FOLDER, FILE_MISSING
    implicit none
    private

    public :: atomic_open, atomic_commit, atomic_abort, write_kv, read_kv, all_finite
    public :: make_dir, remove_file, process_id, path_fits

    !> The longest path the system takes (bytes, with its terminating null: Linux's
    !! PATH_MAX) and the longest part of one (NAME_MAX).
    integer, parameter, public :: PATH_MAX = 4096, NAME_MAX = 255

    !> Write `key = value` on one line; reals in full precision, logicals as yes/no.
    !! The last argument is the writer's iostat: nothing is written when it is already
    !! non-zero on entry, and it receives the write's iostat.
    interface write_kv
        module procedure write_kv_real, write_kv_int, write_kv_char, write_kv_logical
    end interface write_kv

    !> One file of a run.
    type :: out_entry_t
        character(len=:), allocatable :: path       !! final name
        character(len=:), allocatable :: tmp        !! temporary name while written
        integer :: unit = -1                        !! open unit, -1 once closed
        integer :: state = 0                        !! ENTRY_* below
    end type out_entry_t
    integer, parameter :: ENTRY_GONE = 0, ENTRY_OPEN = 1, ENTRY_STAGED = 2, ENTRY_COMMITTED = 3

    !> The files of one run: opened, staged (written and checked, under the temporary
    !! name), committed all together or removed all together.
    type, public :: out_files_t
        private
        type(out_entry_t), allocatable :: f(:)
        integer :: n = 0
    contains
        procedure :: open => files_open
        procedure :: close => files_close
        procedure :: commit => files_commit
        procedure :: discard => files_discard
        procedure :: count => files_count
        procedure :: path => files_path
        procedure :: waiting => files_waiting
        procedure :: temporary => files_temporary
    end type out_files_t

    !> Tries of temporary names PATH.tmp.PID.N before giving up.
    integer, parameter :: MAX_TMP_TRIES = 1000

    interface
        !> C library rename(2): atomic within one file system.
        integer(c_int) function c_rename(old, new) bind(C, name='rename')
            import :: c_int, c_char
            character(kind=c_char), dimension(*), intent(in) :: old    !! null-terminated
            character(kind=c_char), dimension(*), intent(in) :: new    !! null-terminated
        end function c_rename
        !> C library unlink(2).
        integer(c_int) function c_unlink(path) bind(C, name='unlink')
            import :: c_int, c_char
            character(kind=c_char), dimension(*), intent(in) :: path   !! null-terminated
        end function c_unlink
        !> C library mkdir(2); mode_t is an unsigned int on the systems we build for.
        integer(c_int) function c_mkdir(path, mode) bind(C, name='mkdir')
            import :: c_int, c_char
            character(kind=c_char), dimension(*), intent(in) :: path   !! null-terminated
            integer(c_int), value :: mode
        end function c_mkdir
        !> C library rmdir(2).
        integer(c_int) function c_rmdir(path) bind(C, name='rmdir')
            import :: c_int, c_char
            character(kind=c_char), dimension(*), intent(in) :: path   !! null-terminated
        end function c_rmdir
        !> C library access(2).
        integer(c_int) function c_access(path, mode) bind(C, name='access')
            import :: c_int, c_char
            character(kind=c_char), dimension(*), intent(in) :: path   !! null-terminated
            integer(c_int), value :: mode
        end function c_access
        !> C library getpid(2); pid_t is an int.
        integer(c_int) function c_getpid() bind(C, name='getpid')
            import :: c_int
        end function c_getpid
        !> C library opendir(3), dirfd(3), closedir(3) and flock(2): the folder lock.
        type(c_ptr) function c_opendir(path) bind(C, name='opendir')
            import :: c_ptr, c_char
            character(kind=c_char), dimension(*), intent(in) :: path   !! null-terminated
        end function c_opendir
        integer(c_int) function c_dirfd(dir) bind(C, name='dirfd')
            import :: c_int, c_ptr
            type(c_ptr), value :: dir
        end function c_dirfd
        integer(c_int) function c_closedir(dir) bind(C, name='closedir')
            import :: c_int, c_ptr
            type(c_ptr), value :: dir
        end function c_closedir
        integer(c_int) function c_flock(fd, operation) bind(C, name='flock')
            import :: c_int
            integer(c_int), value :: fd, operation
        end function c_flock
    end interface
    integer(c_int), parameter :: LOCK_EX = 2, W_OK = 2, X_OK = 1

contains

    ! ---------------------------------------------------------------- one file

    !> Open a new temporary file PATH.tmp.PID.N (N the first free number, created
    !! exclusively, so no two processes and no two files of one process share it) for
    !! formatted sequential writing.
    subroutine atomic_open(path, unit, stat)
        character(len=*), intent(in) :: path        !! final file name
        integer, intent(out) :: unit                !! unit to write to
        type(status_t), intent(out) :: stat         !! ERR_IO when no temporary file can be made
        integer :: ios, k
        logical :: exists
        character(len=512) :: msg
        character(len=:), allocatable :: tmp, base
        stat%code = STATUS_OK
        unit = -1
        base = path//'.tmp.'//itoa(int(c_getpid()))//'.'
        do k = 1, MAX_TMP_TRIES
            tmp = base//itoa(k)
            msg = ''
            call signals_track(tmp)
            open (newunit=unit, file=tmp, status='new', action='write', form='formatted', &
                  access='sequential', iostat=ios, iomsg=msg)
            if (ios == 0) then
                call signals_created(tmp)
                return
            end if
            call signals_untrack(tmp)
            unit = -1
            inquire (file=tmp, exist=exists)
            if (.not. exists) exit          ! not a name clash: the folder is the problem
        end do
        call set_error(stat, ERR_IO, 'cannot open '//tmp//' for writing: '//trim(msg))
    end subroutine atomic_open

    !> Check and close a unit from atomic_open and rename its temporary file to PATH; on any
    !! failure the temporary file is removed and PATH left untouched.
    subroutine atomic_commit(unit, path, stat, ios)
        integer, intent(in) :: unit                 !! unit from atomic_open
        character(len=*), intent(in) :: path        !! final file name
        type(status_t), intent(out) :: stat         !! ERR_IO when a write, the close or the rename failed
        integer, intent(in), optional :: ios        !! iostat of the writer's writes (0: all ok)
        character(len=:), allocatable :: tmp
        integer :: wios
        wios = 0
        if (present(ios)) wios = ios
        call finish_unit(unit, path, wios, tmp, stat)
        if (stat%code /= STATUS_OK) return
        if (c_rename(tmp//c_null_char, path//c_null_char) /= 0) then
            call set_error(stat, ERR_IO, 'cannot rename '//tmp//' to '//path)
            call remove_file(tmp)
        end if
        call signals_untrack(tmp)
    end subroutine atomic_commit

    !> Give up a file from atomic_open: close the unit deleting its temporary file; PATH is
    !! left untouched.
    subroutine atomic_abort(unit, path)
        integer, intent(in) :: unit                 !! unit from atomic_open
        character(len=*), intent(in) :: path        !! final file name (as given to atomic_open)
        logical :: opened
        integer :: ios
        character(len=:), allocatable :: tmp
        opened = .false.
        if (unit /= -1) inquire (unit=unit, opened=opened, iostat=ios)
        if (.not. opened) return
        tmp = unit_name(unit)
        if (index(tmp, path//'.tmp.') /= 1) then    ! not a temporary file of path: keep it
            close (unit, iostat=ios)
            return
        end if
        close (unit, status='delete', iostat=ios)
        call remove_file(tmp)                       ! whatever the close did
        call signals_untrack(tmp)
    end subroutine atomic_abort

    !> Flush, check and close a unit from atomic_open: ERR_IO (and the temporary file
    !! removed) when the writer's iostat is non-zero, the flush or the close fails, or the
    !! file on disk is shorter or longer than what was written (a full disk).
    subroutine finish_unit(unit, path, wios, tmp, stat)
        integer, intent(in) :: unit                 !! open unit from atomic_open
        character(len=*), intent(in) :: path        !! final file name (for messages)
        integer, intent(in) :: wios                 !! iostat of the writer's writes
        character(len=:), allocatable, intent(out) :: tmp   !! the temporary file's name
        type(status_t), intent(out) :: stat         !! ERR_IO on any failure
        integer :: ios
        integer(int64) :: written, on_disk
        character(len=512) :: msg
        stat%code = STATUS_OK
        tmp = unit_name(unit)
        msg = ''
        if (wios /= 0) then
            call set_error(stat, ERR_IO, 'cannot write '//path//' (iostat '//itoa(wios)//')')
            close (unit, status='delete', iostat=ios)
            call remove_file(tmp)
            call signals_untrack(tmp)
            return
        end if
        flush (unit, iostat=ios, iomsg=msg)
        written = -1
        if (ios == 0) inquire (unit=unit, size=written, iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_IO, 'cannot write '//path//': '//trim(msg))
            close (unit, status='delete', iostat=ios)
            call remove_file(tmp)
            call signals_untrack(tmp)
            return
        end if
        close (unit, iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_IO, 'cannot close '//path//': '//trim(msg))
            call remove_file(tmp)
            call signals_untrack(tmp)
            return
        end if
        on_disk = -1
        inquire (file=tmp, size=on_disk, iostat=ios)
        if (written >= 0 .and. on_disk /= written) then
            ! (on a full disk the run-time library's count of what it wrote may itself be
            ! short of what the program wrote: only a shorter file is certain)
            if (on_disk >= 0 .and. on_disk < written) then
                call set_error(stat, ERR_IO, 'cannot write '//path//': only '// &
                    itoa64(on_disk)//' of its '//itoa64(written)//' bytes reached the disk '// &
                    '(disk full?)')
            else
                call set_error(stat, ERR_IO, 'cannot write '//path//': the file on the '// &
                    'disk ('//itoa64(on_disk)//' bytes) is not what was written (disk full?)')
            end if
            call remove_file(tmp)
            call signals_untrack(tmp)
        end if
    end subroutine finish_unit

    !> The file name of an open unit ('' when unknown).
    function unit_name(unit) result(nm)
        integer, intent(in) :: unit
        character(len=:), allocatable :: nm
        character(len=4096) :: buf
        integer :: ios
        buf = ''
        inquire (unit=unit, name=buf, iostat=ios)
        nm = trim(buf)
        if (ios /= 0) nm = ''
    end function unit_name

    !> Remove a file if it exists (errors ignored).
    subroutine remove_file(path)
        character(len=*), intent(in) :: path        !! file name
        integer(c_int) :: rc
        rc = c_unlink(path//c_null_char)
    end subroutine remove_file

    !> This process's id (as in the temporary names).
    integer function process_id()
        process_id = int(c_getpid())
    end function process_id

    ! ---------------------------------------------------------------- the files of a run

    !> Open a file of the run (atomic_open) and register it.
    subroutine files_open(self, path, unit, stat)
        class(out_files_t), intent(inout) :: self
        character(len=*), intent(in) :: path        !! final file name
        integer, intent(out) :: unit                !! unit to write to
        type(status_t), intent(out) :: stat         !! ERR_IO
        type(out_entry_t), allocatable :: grown(:)
        call atomic_open(path, unit, stat)
        if (stat%code /= STATUS_OK) return
        if (.not. allocated(self%f)) allocate (self%f(8))
        if (self%n == size(self%f)) then
            allocate (grown(2*self%n))
            grown(1:self%n) = self%f
            call move_alloc(grown, self%f)
        end if
        self%n = self%n + 1
        self%f(self%n)%path = path
        self%f(self%n)%tmp = unit_name(unit)
        self%f(self%n)%unit = unit
        self%f(self%n)%state = ENTRY_OPEN
    end subroutine files_open

    !> A file of the run is written: check and close it (see finish_unit); it then waits
    !! under its temporary name for %commit.  On failure it is removed (ERR_IO).
    subroutine files_close(self, unit, ios, stat)
        class(out_files_t), intent(inout) :: self
        integer, intent(in) :: unit                 !! unit from %open
        integer, intent(in) :: ios                  !! iostat of the writer's writes
        type(status_t), intent(out) :: stat         !! ERR_IO
        character(len=:), allocatable :: tmp
        integer :: k
        stat%code = STATUS_OK
        do k = 1, self%n
            if (self%f(k)%state == ENTRY_OPEN .and. self%f(k)%unit == unit) exit
        end do
        if (k > self%n) then
            call set_error(stat, ERR_IO, 'output: unit '//itoa(unit)//' is no file of this run')
            return
        end if
        call finish_unit(unit, self%f(k)%path, ios, tmp, stat)
        self%f(k)%unit = -1
        if (stat%code == STATUS_OK) then
            self%f(k)%state = ENTRY_STAGED
        else
            self%f(k)%state = ENTRY_GONE
        end if
    end subroutine files_close

    !> Rename every staged file of the run to its final name, under an exclusive lock on
    !! the folder of the first one, then (under the same lock) remove the files `stale`
    !! that this run did not write: files of an earlier run that the run's analyses could
    !! have written (an old NAME.fit.dat beside a new NAME.identify).  A file still open is
    !! an error.  On any failure every file of the run is removed, those already renamed
    !! included, and the stale ones are left (ERR_IO).
    subroutine files_commit(self, stat, stale)
        class(out_files_t), intent(inout) :: self
        type(status_t), intent(out) :: stat         !! ERR_IO
        character(len=*), intent(in), optional :: stale(:)  !! paths (trailing blanks dropped)
        type(c_ptr) :: dir
        integer(c_int) :: rc
        integer :: k, j
        logical :: ours
        stat%code = STATUS_OK
        do k = 1, self%n
            if (self%f(k)%state == ENTRY_OPEN) then
                call set_error(stat, ERR_IO, 'output: '//self%f(k)%path//' was never closed')
                call self%discard()
                return
            end if
        end do
        dir = c_null_ptr
        if (self%n > 0) dir = c_opendir(folder_of(self%f(1)%path)//c_null_char)
        if (c_associated(dir)) rc = c_flock(c_dirfd(dir), LOCK_EX)
        do k = 1, self%n
            if (self%f(k)%state /= ENTRY_STAGED) cycle
            if (c_rename(self%f(k)%tmp//c_null_char, self%f(k)%path//c_null_char) /= 0) then
                call set_error(stat, ERR_IO, 'cannot rename '//self%f(k)%tmp//' to '// &
                               self%f(k)%path)
                exit
            end if
            call signals_untrack(self%f(k)%tmp)
            self%f(k)%state = ENTRY_COMMITTED
        end do
        if (stat%code == STATUS_OK .and. present(stale)) then
            do j = 1, size(stale)
                if (len_trim(stale(j)) == 0) cycle
                ours = .false.
                do k = 1, self%n
                    if (self%f(k)%state /= ENTRY_COMMITTED) cycle
                    if (self%f(k)%path == trim(stale(j))) ours = .true.
                end do
                if (.not. ours) call remove_file(trim(stale(j)))
            end do
        end if
        if (c_associated(dir)) rc = c_closedir(dir)      ! releases the lock
        if (stat%code /= STATUS_OK) call self%discard()
    end subroutine files_commit

    !> Remove every file of the run: open ones are closed and deleted, staged temporary
    !! files deleted, committed files removed.
    subroutine files_discard(self)
        class(out_files_t), intent(inout) :: self
        integer :: k, ios
        logical :: opened
        do k = 1, self%n
            select case (self%f(k)%state)
            case (ENTRY_OPEN)
                inquire (unit=self%f(k)%unit, opened=opened, iostat=ios)
                if (opened) close (self%f(k)%unit, status='delete', iostat=ios)
                call remove_file(self%f(k)%tmp)
                call signals_untrack(self%f(k)%tmp)
            case (ENTRY_STAGED)
                call remove_file(self%f(k)%tmp)
                call signals_untrack(self%f(k)%tmp)
            case (ENTRY_COMMITTED)
                call remove_file(self%f(k)%path)
            end select
            self%f(k)%state = ENTRY_GONE
            self%f(k)%unit = -1
        end do
    end subroutine files_discard

    !> Number of files of the run committed so far (after %commit: all of them).
    integer function files_count(self)
        class(out_files_t), intent(in) :: self
        integer :: k
        files_count = 0
        do k = 1, self%n
            if (self%f(k)%state == ENTRY_COMMITTED) files_count = files_count + 1
        end do
    end function files_count

    !> Final name of the k-th committed file of the run.
    function files_path(self, k) result(p)
        class(out_files_t), intent(in) :: self
        integer, intent(in) :: k                    !! 1 .. %count()
        character(len=:), allocatable :: p
        integer :: i, m
        p = ''
        m = 0
        do i = 1, self%n
            if (self%f(i)%state /= ENTRY_COMMITTED) cycle
            m = m + 1
            if (m == k) then
                p = self%f(i)%path
                return
            end if
        end do
    end function files_path

    !> Number of files of the run still under their temporary names (open or staged).
    integer function files_waiting(self)
        class(out_files_t), intent(in) :: self
        integer :: k
        files_waiting = 0
        do k = 1, self%n
            if (self%f(k)%state == ENTRY_OPEN .or. self%f(k)%state == ENTRY_STAGED) &
                files_waiting = files_waiting + 1
        end do
    end function files_waiting

    !> Temporary name of the k-th file of the run still under it ('' when there is none).
    function files_temporary(self, k) result(p)
        class(out_files_t), intent(in) :: self
        integer, intent(in) :: k                    !! 1 .. %waiting()
        character(len=:), allocatable :: p
        integer :: i, m
        p = ''
        m = 0
        do i = 1, self%n
            if (self%f(i)%state /= ENTRY_OPEN .and. self%f(i)%state /= ENTRY_STAGED) cycle
            m = m + 1
            if (m == k) then
                p = self%f(i)%tmp
                return
            end if
        end do
    end function files_temporary

    !> The folder part of a path ('.' when none).
    pure function folder_of(path) result(dir)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: dir
        integer :: i
        i = index(path, '/', back=.true.)
        if (i == 0) then
            dir = '.'
        else if (i == 1) then
            dir = '/'
        else
            dir = path(1:i - 1)
        end if
    end function folder_of

    ! ---------------------------------------------------------------- folders

    !> Create the folder `dir` and its parents when missing (as mkdir -p; mode 0777 less
    !! the umask), then check that it is a folder that can be written.  A name the system
    !! cannot take, with room for the run's files in it (path_fits with a name of `room`
    !! characters), is refused before anything is created; on any failure the folders made
    !! here are removed again.
    subroutine make_dir(dir, stat, room)
        character(len=*), intent(in) :: dir         !! folder name, not empty
        type(status_t), intent(out) :: stat         !! ERR_IO when it cannot be made or written
        integer, intent(in), optional :: room       !! longest file name to fit in it (default 64)
        integer :: i, nmade, r
        integer(c_int) :: rc
        integer, allocatable :: made(:)
        character(len=:), allocatable :: why
        stat%code = STATUS_OK
        if (len(dir) == 0) then
            call set_error(stat, ERR_IO, 'output folder: an empty name')
            return
        end if
        r = 64
        if (present(room)) r = room
        call path_fits(dir, repeat('x', r), stat)
        if (stat%code /= STATUS_OK) then
            why = ''
            if (len(dir) + r + 25 <= PATH_MAX - 1) why = ' with a part longer than '// &
                itoa(NAME_MAX)
            call set_error(stat, ERR_IO, 'output folder '//clipped(dir)//': a name of '// &
                itoa(len(dir))//' characters'//why//'; allowed: at most '// &
                itoa(PATH_MAX - 1 - r - 25)//' characters (the system''s PATH_MAX less room '// &
                'for the files in it), each part at most '//itoa(NAME_MAX)// &
                ' (NAME_MAX); nothing was created')
            return
        end if
        allocate (made(len(dir)))
        nmade = 0
        do i = 2, len(dir)
            if (dir(i:i) == '/' .and. dir(i - 1:i - 1) /= '/') call mk(i - 1)
        end do
        call mk(len(dir))
        if (c_access(dir//'/.'//c_null_char, 0_c_int) /= 0) then
            call set_error(stat, ERR_IO, 'cannot create the output folder '//dir// &
                           why_not_made()//'; allowed: a folder that can be written, or a '// &
                           'name not yet taken in one')
        else if (c_access(dir//'/.'//c_null_char, W_OK + X_OK) /= 0) then
            call set_error(stat, ERR_IO, 'cannot write into the output folder '//dir)
        end if
        if (stat%code /= STATUS_OK) then
            do i = nmade, 1, -1                     ! what was made, deepest first
                rc = c_rmdir(dir(1:made(i))//c_null_char)
            end do
        end if

    contains

        !> Why dir could not be made: the first part of it that exists and is no folder, or
        !! the last folder on the way that cannot be written.
        function why_not_made() result(w)
            character(len=:), allocatable :: w
            integer :: j, k, last
            w = ''
            last = 0
            do j = 1, len(dir)
                if (j < len(dir)) then
                    if (dir(j + 1:j + 1) /= '/' .or. dir(j:j) == '/') cycle
                end if
                k = kind_of_file(dir(1:j))
                if (k == FILE_FOLDER) then
                    last = j
                else if (k /= FILE_MISSING) then
                    w = ': '//dir(1:j)//' is '//trim(kind_name(k))//', not a folder'
                    return
                else
                    exit
                end if
            end do
            if (last > 0) then
                if (c_access(dir(1:last)//'/.'//c_null_char, W_OK + X_OK) /= 0) &
                    w = ': the folder '//dir(1:last)//' cannot be written'
            else if (dir(1:1) /= '/') then
                if (c_access('.'//c_null_char, W_OK + X_OK) /= 0) &
                    w = ': the current folder cannot be written'
            end if
        end function why_not_made

        !> mkdir of dir(1:m); remembered when made here.
        subroutine mk(m)
            integer, intent(in) :: m
            if (c_mkdir(dir(1:m)//c_null_char, int(o'777', c_int)) == 0) then
                nmade = nmade + 1
                made(nmade) = m
            end if
        end subroutine mk

    end subroutine make_dir

    !> Whether the system can take the path dir/name: at most PATH_MAX - 1 bytes, with room
    !! for a temporary name's '.tmp.PID.N' (24 more), and no part longer than NAME_MAX
    !! (the name with that suffix included).  ERR_IO naming the limit otherwise.
    subroutine path_fits(dir, name, stat)
        character(len=*), intent(in) :: dir         !! the folder
        character(len=*), intent(in) :: name        !! a file name in it (the longest)
        type(status_t), intent(out) :: stat         !! ERR_IO
        integer, parameter :: TMP_SUFFIX = 24       !! '.tmp.' PID (<= 10) '.' N (<= 4), spare
        integer :: i, j, longest
        stat%code = STATUS_OK
        if (len(dir) + 1 + len(name) + TMP_SUFFIX > PATH_MAX - 1) then
            call set_error(stat, ERR_IO, 'the path '//clipped(dir)//'/'//clipped(name)// &
                ' would be '//itoa(len(dir) + 1 + len(name) + TMP_SUFFIX)//' characters '// &
                'with a temporary suffix; allowed: at most '//itoa(PATH_MAX - 1)// &
                ' (the system''s PATH_MAX)')
            return
        end if
        longest = len(name) + TMP_SUFFIX
        j = 0
        do i = 1, len(dir) + 1
            if (i > len(dir)) then
                longest = max(longest, i - 1 - j)
            else if (dir(i:i) == '/') then
                longest = max(longest, i - 1 - j)
                j = i
            end if
        end do
        if (longest > NAME_MAX) call set_error(stat, ERR_IO, 'the path '//clipped(dir)//'/'// &
            clipped(name)//' has a part of '//itoa(longest)//' characters (with a '// &
            'temporary suffix); allowed: at most '//itoa(NAME_MAX)//' (the system''s NAME_MAX)')

    end subroutine path_fits

    !> s, or its first and last 40 characters around ' ... ' when longer than 100.
    pure function clipped(s) result(c)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: c
        if (len(s) <= 100) then
            c = s
        else
            c = s(1:40)//' ... '//s(len(s) - 39:)
        end if
    end function clipped

    ! ---------------------------------------------------------------- key = value

    !> `key = value` for a real, in full precision (17 significant digits).
    subroutine write_kv_real(unit, key, value, ios)
        integer, intent(in) :: unit                 !! open formatted unit
        character(len=*), intent(in) :: key         !! key
        real(dp), intent(in) :: value               !! value
        integer, intent(inout) :: ios               !! writer's iostat: skip when /= 0
        character(len=32) :: buf
        if (ios /= 0) return
        write (buf, '(es25.16e3)') value
        write (unit, '(a)', iostat=ios) key//' = '//trim(adjustl(buf))
    end subroutine write_kv_real

    !> `key = value` for an integer.
    subroutine write_kv_int(unit, key, value, ios)
        integer, intent(in) :: unit                 !! open formatted unit
        character(len=*), intent(in) :: key         !! key
        integer, intent(in) :: value                !! value
        integer, intent(inout) :: ios               !! writer's iostat: skip when /= 0
        if (ios /= 0) return
        write (unit, '(a,i0)', iostat=ios) key//' = ', value
    end subroutine write_kv_int

    !> `key = value` for a character string (trailing blanks dropped).
    subroutine write_kv_char(unit, key, value, ios)
        integer, intent(in) :: unit                 !! open formatted unit
        character(len=*), intent(in) :: key         !! key
        character(len=*), intent(in) :: value       !! value
        integer, intent(inout) :: ios               !! writer's iostat: skip when /= 0
        if (ios /= 0) return
        write (unit, '(a)', iostat=ios) key//' = '//trim(value)
    end subroutine write_kv_char

    !> `key = yes` or `key = no`.
    subroutine write_kv_logical(unit, key, value, ios)
        integer, intent(in) :: unit                 !! open formatted unit
        character(len=*), intent(in) :: key         !! key
        logical, intent(in) :: value                !! value
        integer, intent(inout) :: ios               !! writer's iostat: skip when /= 0
        if (ios /= 0) return
        if (value) then
            write (unit, '(a)', iostat=ios) key//' = yes'
        else
            write (unit, '(a)', iostat=ios) key//' = no'
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

    !> An int64 without blanks.
    pure function itoa64(i) result(s)
        integer(int64), intent(in) :: i
        character(len=:), allocatable :: s
        character(len=24) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function itoa64

end module output_io
