!> One result from several releases: the pooled estimate, its random (Type A) standard
!! uncertainty with its degrees of freedom, and whether the releases agree.
!!
!! Each release r gives an estimate x_r with its own standard uncertainty u_r (what that
!! release alone knows: its timing scatter, its record's noise, the inputs measured anew for
!! it) on nu_r degrees of freedom.  Components common to every release (mass, g, one
!! tape's calibration) are not here: they enter the final budget once, not averaged down.
!!
!! * Consistency: chi^2 = sum w_r (x_r - xbar_w)^2 with w_r = 1/u_r^2 and xbar_w the
!!   weighted mean; the Birge ratio R_B = (chi^2/(n - 1))^(1/2); the releases disagree when
!!   P(chi^2_{n-1} >= chi^2) < 0.05.
!! * Consistent releases: the weighted mean, u_int = (sum w_r)^(-1/2) with the
!!   Welch-Satterthwaite degrees of freedom of its parts.
!! * Inconsistent releases: the scatter between them is a component of its own (the
!!   reproducibility of a release, tau^2, by the method of moments of DerSimonian and Laird,
!!   Controlled Clinical Trials 7 (1986) 177): weights 1/(u_r^2 + tau^2), u of that mean
!!   (sum 1/(u_r^2 + tau^2))^(-1/2), n - 1 degrees of freedom.
!! * Releases without their own u (one timed period each, say): the plain mean, untested.
!! * In every case the random u is never below the standard error of the releases' mean,
!!   s/n^(1/2) (s their standard deviation), which then carries n - 1 degrees of freedom.
!!   u_reproducibility = (u_random^2 - u_int^2)^(1/2) is what the scatter added.
!!
!! Releases in sessions (pool_sessions): a session is what the releases of one sitting
!! share (the hanging, the instrument's setting, the day), so its releases scatter about
!! their session's mean, and the sessions' means about the truth.  Two levels:
!! * within each session its releases are pooled as above (pool_releases): the session's
!!   I1_s with its u_s and degrees of freedom;
!! * the sessions' I1_s are pooled as above in turn, tested for consistency (the session
!!   Birge ratio), with the scatter between sessions (tau^2 of DerSimonian and Laird when
!!   they disagree; never below the standard error of the sessions' mean) a component of
!!   its own.
!! The pooled u splits into the releases' part within the sessions,
!! u_within^2 = sum W_s^2 u_s^2 (W_s the sessions' weights; its degrees of freedom by
!! Welch-Satterthwaite of the sessions'), and the sessions' part,
!! u_session = (u^2 - u_within^2)^(1/2), on n_sessions - 1 degrees of freedom.  Each
!! release's weight in the pooled mean is its session's weight times its weight within the
!! session.  The releases within the sessions are tested together: chi^2 the sum of the
!! sessions' on sum (n_s - 1) degrees of freedom.  When the sessions disagree, the one
!! furthest from the pooled mean of the others (in units of the u of their difference,
!! each session's own u) is named; `alone` says whether the others then agree.
!! With fewer than two sessions the releases are pooled in one level (pool_releases).
module pooling
    use kinds, only: dp
    use stats, only: chi2_sf, welch_satterthwaite, NU_INFINITE
    implicit none
    private

    !> Level of the chi-square test of consistency.
    real(dp), parameter, public :: CONSISTENCY_LEVEL = 0.05_dp

    !> Several releases pooled.
    type, public :: pooled_t
        integer :: n = 0                        !! releases
        real(dp) :: mean = 0.0_dp               !! the pooled estimate
        real(dp) :: u_int = 0.0_dp              !! from the releases' own u
        real(dp) :: sem = 0.0_dp                !! standard error of the releases' mean
        real(dp) :: chi2 = 0.0_dp, birge = -1.0_dp, p_value = -1.0_dp   !! -1: not tested
        real(dp) :: tau = 0.0_dp                !! reproducibility of one release (0: none)
        real(dp) :: u_random = 0.0_dp           !! the pooled estimate's random u
        real(dp) :: nu_random = NU_INFINITE     !! its degrees of freedom
        real(dp) :: u_reproducibility = 0.0_dp  !! (u_random^2 - u_int^2)^(1/2)
        real(dp), allocatable :: weight(:)      !! each release's weight (sum 1)
        !> 'single release', 'consistent', 'inconsistent' or 'not tested'
        character(len=14) :: consistency = 'single release'
    end type pooled_t

    !> Releases pooled in sessions (pool_sessions).
    type, public :: sessions_pooled_t
        integer :: n_sessions = 0               !! distinct sessions
        character(len=64), allocatable :: label(:)  !! each session's label, first seen first
        integer, allocatable :: of_release(:)   !! each release's session (index in label)
        integer, allocatable :: n_releases(:)   !! each session's releases
        type(pooled_t), allocatable :: within(:)    !! each session's releases pooled
        type(pooled_t) :: between               !! the sessions' I1_s pooled
        !> the pooled result over the releases: mean, u_random (both levels), nu_random,
        !! weight (each release's), and the within-session test (chi2, birge, p_value,
        !! consistency) when n_sessions >= 2; else pool_releases' one level
        type(pooled_t) :: pool
        real(dp) :: u_within = 0.0_dp           !! the releases' part within the sessions
        real(dp) :: nu_within = NU_INFINITE     !! its degrees of freedom
        real(dp) :: u_session = 0.0_dp          !! the sessions' part (between them)
        real(dp) :: nu_session = NU_INFINITE    !! its degrees of freedom (n_sessions - 1)
        integer :: outlier = 0                  !! the session furthest from the others
        real(dp) :: outlier_z = 0.0_dp          !! its distance in u of the difference
        logical :: alone = .false.              !! the others agree without it
    end type sessions_pooled_t

    public :: pool_releases, pool_sessions

contains

    !> Pool n >= 1 releases (see the module header).
    pure subroutine pool_releases(x, u, nu, pool)
        real(dp), intent(in) :: x(:)            !! each release's estimate
        real(dp), intent(in) :: u(:)            !! its own standard uncertainty (>= 0)
        real(dp), intent(in) :: nu(:)           !! its degrees of freedom (NU_INFINITE: B)
        type(pooled_t), intent(out) :: pool
        real(dp) :: w(size(x)), ws, s, xbar, t2, part(size(x))
        integer :: n
        n = size(x)
        pool%n = n
        allocate (pool%weight(n))
        if (n == 1) then
            pool%mean = x(1)
            pool%u_int = u(1)
            pool%u_random = u(1)
            pool%nu_random = nu(1)
            pool%weight = 1.0_dp
            return
        end if
        xbar = sum(x)/n
        s = sqrt(sum((x - xbar)**2)/(n - 1))
        pool%sem = s/sqrt(real(n, dp))
        if (all(u > 0.0_dp)) then
            w = 1.0_dp/u**2
            ws = sum(w)
            pool%mean = sum(w*x)/ws
            pool%u_int = 1.0_dp/sqrt(ws)
            pool%chi2 = sum(w*(x - pool%mean)**2)
            pool%birge = sqrt(pool%chi2/(n - 1))
            pool%p_value = chi2_sf(pool%chi2, real(n - 1, dp))
            if (pool%p_value >= CONSISTENCY_LEVEL) then
                pool%consistency = 'consistent'
                pool%weight = w/ws
                pool%u_random = pool%u_int
                part = pool%weight*u
                pool%nu_random = min(NU_INFINITE, pool%u_int**4/sum(part**4/nu))
            else
                pool%consistency = 'inconsistent'
                t2 = max(0.0_dp, (pool%chi2 - (n - 1))/(ws - sum(w**2)/ws))
                pool%tau = sqrt(t2)
                w = 1.0_dp/(u**2 + t2)
                pool%weight = w/sum(w)
                pool%mean = sum(w*x)/sum(w)
                pool%u_random = 1.0_dp/sqrt(sum(w))
                pool%nu_random = n - 1
            end if
        else
            pool%consistency = 'not tested'
            pool%mean = xbar
            pool%weight = 1.0_dp/n
            pool%u_int = sqrt(sum(u**2))/n
            pool%u_random = pool%u_int
            pool%nu_random = n - 1
        end if
        if (pool%sem > pool%u_random) then
            pool%u_random = pool%sem
            pool%nu_random = n - 1
        end if
        pool%u_reproducibility = sqrt(max(0.0_dp, pool%u_random**2 - pool%u_int**2))
    end subroutine pool_releases

    !> Pool n >= 1 releases in their sessions (see the module header).
    pure subroutine pool_sessions(x, u, nu, session, sp)
        real(dp), intent(in) :: x(:)            !! each release's estimate
        real(dp), intent(in) :: u(:)            !! its own standard uncertainty (>= 0)
        real(dp), intent(in) :: nu(:)           !! its degrees of freedom (NU_INFINITE: B)
        character(len=*), intent(in) :: session(:)  !! its session's label
        type(sessions_pooled_t), intent(out) :: sp
        real(dp), allocatable :: xs(:), us(:), nus(:), part(:)
        real(dp) :: chi2, dof, z, zmax
        type(pooled_t) :: rest
        integer :: n, r, s, ns, k
        integer, allocatable :: idx(:)
        n = size(x)
        allocate (sp%of_release(n), sp%label(0))
        do r = 1, n
            k = 0
            do s = 1, size(sp%label)
                if (sp%label(s) == session(r)) k = s
            end do
            if (k == 0) then
                sp%label = [sp%label, session(r)(1:min(64, len(session(r))))]
                k = size(sp%label)
            end if
            sp%of_release(r) = k
        end do
        ns = size(sp%label)
        sp%n_sessions = ns
        if (ns < 2) then
            call pool_releases(x, u, nu, sp%pool)
            return
        end if
        allocate (sp%within(ns), sp%n_releases(ns), xs(ns), us(ns), nus(ns))
        chi2 = 0.0_dp
        dof = 0.0_dp
        do s = 1, ns
            idx = pack([(r, r=1, n)], sp%of_release == s)
            sp%n_releases(s) = size(idx)
            call pool_releases(x(idx), u(idx), nu(idx), sp%within(s))
            xs(s) = sp%within(s)%mean
            us(s) = sp%within(s)%u_random
            nus(s) = sp%within(s)%nu_random
            if (sp%within(s)%p_value >= 0.0_dp) then
                chi2 = chi2 + sp%within(s)%chi2
                dof = dof + (size(idx) - 1)
            end if
        end do
        call pool_releases(xs, us, nus, sp%between)
        ! the pooled result over the releases
        sp%pool%n = n
        sp%pool%mean = sp%between%mean
        sp%pool%u_random = sp%between%u_random
        sp%pool%nu_random = sp%between%nu_random
        sp%pool%sem = sp%between%sem
        allocate (sp%pool%weight(n))
        do r = 1, n
            s = sp%of_release(r)
            k = count(sp%of_release(1:r) == s)
            sp%pool%weight(r) = sp%between%weight(s)*sp%within(s)%weight(k)
        end do
        part = sp%between%weight*us
        sp%u_within = sqrt(sum(part**2))
        sp%nu_within = welch_satterthwaite(part, nus)
        sp%pool%u_int = sp%u_within
        sp%u_session = sqrt(max(0.0_dp, sp%between%u_random**2 - sp%u_within**2))
        sp%nu_session = ns - 1
        sp%pool%u_reproducibility = sp%u_session
        sp%pool%consistency = 'not tested'
        if (dof > 0.0_dp) then
            sp%pool%chi2 = chi2
            sp%pool%birge = sqrt(chi2/dof)
            sp%pool%p_value = chi2_sf(chi2, dof)
            sp%pool%consistency = trim(merge('consistent  ', 'inconsistent', &
                                             sp%pool%p_value >= CONSISTENCY_LEVEL))
        else if (all(sp%n_releases == 1)) then
            sp%pool%consistency = 'single release'
        end if
        ! the session furthest from the pooled mean of the others
        if (ns >= 3 .and. all(us > 0.0_dp)) then
            zmax = -1.0_dp
            do s = 1, ns
                idx = pack([(k, k=1, ns)], [(k, k=1, ns)] /= s)
                call pool_releases(xs(idx), us(idx), nus(idx), rest)
                z = abs(xs(s) - rest%mean)/sqrt(us(s)**2 + rest%u_int**2)
                if (z > zmax) then
                    zmax = z
                    sp%outlier = s
                    sp%outlier_z = z
                    sp%alone = ns == 2 .or. trim(rest%consistency) /= 'inconsistent'
                end if
            end do
        end if
    end subroutine pool_sessions

end module pooling
