!> The types of a physical rig and of how it starts (rig_t, start_t), in the deck's units,
!! with the deck's defaults (module rig_groups): apart from module rig, which builds them
!! from the deck's groups and scales them for the model, so that a measurement's model
!! (module measurement) holds a release's rig without the runs above it.
module rig_type
    use kinds, only: dp
    use rig_groups, only: DEFAULT_B, DEFAULT_B_PRIME, &
        DEFAULT_L, DEFAULT_L_PRIME, DEFAULT_G, DEFAULT_MASS, DEFAULT_INERTIA, DEFAULT_R, &
        DEFAULT_LAMBDA, DEFAULT_BTILDE, DEFAULT_SWAY_DEPTH, DEFAULT_C_V, DEFAULT_C_Q, &
        DEFAULT_STIFFNESS, DEFAULT_CABLE_DAMPING, DEFAULT_MODE, DEFAULT_AMPLITUDE, &
        DEFAULT_TILT, DEFAULT_THETA, DEFAULT_THETA_DOT
    implicit none
    private

    !> The rig, in the deck's units (any one consistent system; time in seconds); by default
    !! the deck's defaults (module rig_groups).
    type, public :: rig_t
        ! the suspension: spacing of the cables on the support (b) and on the body (b_prime),
        ! cable lengths BC (l) and AD (l_prime), gravity
        real(dp) :: b = DEFAULT_B, b_prime = DEFAULT_B_PRIME
        real(dp) :: l = DEFAULT_L, l_prime = DEFAULT_L_PRIME, g = DEFAULT_G
        ! the body: mass, principal moments about its mass centre, the mass centre's place
        ! from C (r, lambda, eq. (21)), the principal axes (btilde, rows in ntilde), the
        ! depth of the point E of the side-sway Q below the midpoint of CD
        real(dp) :: mass = DEFAULT_MASS
        real(dp) :: inertia(3) = DEFAULT_INERTIA
        real(dp) :: r = DEFAULT_R, lambda = DEFAULT_LAMBDA
        real(dp) :: btilde(3, 3) = DEFAULT_BTILDE
        real(dp) :: sway_depth = DEFAULT_SWAY_DEPTH
        ! the damping torque about the vertical, M = -(c_v W + c_q |W| W) n3
        real(dp) :: c_v = DEFAULT_C_V, c_q = DEFAULT_C_Q
        ! elastic cables (model 'elastic'): EA/(m g) and the damping ratio of each cable
        real(dp) :: cable_stiffness = DEFAULT_STIFFNESS, cable_damping = DEFAULT_CABLE_DAMPING
        ! cables > 2: a regular platform of that many cables, b = 2 radius, b_prime = 2
        ! radius_prime, l every cable's length (module platform_rig: platform_of_rig)
        integer :: cables = 2
        ! a platform's mass centre: its y in the body frame (&body cg_offset(2)); its x and
        ! its depth are r cos(lambda) - b_prime/2 and r sin(lambda), as on the bifilar
        real(dp) :: cg_offset_y = 0.0_dp
    end type rig_t

    !> How the rig starts: mode 'raised' (the paper's recipe: turned by `amplitude` degrees
    !! about the vertical through O, tilt added to theta_1) or 'angles' (theta_1..4 and their
    !! rates given); theta_5 and its rate follow from the constraint.
    type, public :: start_t
        character(len=16) :: mode = DEFAULT_MODE
        real(dp) :: amplitude = DEFAULT_AMPLITUDE   !! degrees (mode 'raised')
        real(dp) :: tilt = DEFAULT_TILT             !! rad, added to theta_1 (mode 'raised')
        real(dp) :: theta(4) = DEFAULT_THETA        !! rad (mode 'angles')
        real(dp) :: theta_dot(4) = DEFAULT_THETA_DOT    !! rad per unit tau (mode 'angles')
    end type start_t

end module rig_type
