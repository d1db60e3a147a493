!> The rider's three rigid bodies (thesis 4.3: pelvis, legs, trunk) from de
!> Leva (1996) table 4 (METHOD-PART2 appendix I), scaled to the rider's mass
!> and height. Every choice the thesis leaves open is made here and listed in
!> docs/rider.md ("Body"); keep the two in step.
!>
!> Frames (all right-handed, lengths in m). The rider lies on the back, feet
!> first, legs crossed at the ankles, arms crossed on the chest.
!>   pelvis frame P: origin at the pelvis contact on the slide, x along the
!>     body towards the feet, z the slide normal (away from the slide, i.e. the
!>     rider's anterior direction), y = z x x (the rider's left);
!>   legs frame L and trunk frame T: origin at the hip joint centre (mid-hip),
!>     parallel to P when the joint angles are zero; the legs lie along +x,
!>     the trunk along -x.
!> Every segment centre of mass lies on the body axis, com_height above the
!> slide plane of a straight rider (thesis table 4.10 "Schwerpunkthoehe"); the
!> hip is on that axis too, and the heel and back contacts are com_height
!> below it.
!>
!> Grouping (METHOD-PART2 B.2): pelvis = lower trunk (omphalion - mid-hip);
!> legs = 2 x (thigh + shank + foot); trunk = middle trunk + upper trunk +
!> head and neck + 2 x (upper arm + forearm + hand).
!> Placement along the axis (from the segments' end points and CoM ratios):
!>   pelvis contact under the lower trunk's centre of mass, hip at
!>     (1 - com_LPT) L_LPT towards the feet;
!>   thigh from the hip, shank from the knee, foot centre of mass at the
!>     ankle (feet point up), heel contact under the ankle;
!>   middle trunk from the omphalion (L_LPT from the hip), upper trunk from the
!>     xiphion, head and neck from the suprasternale level (C7 taken at that
!>     level, head in line with the trunk);
!>   arms crossed on the chest: all six arm segments with their centres of
!>     mass at the upper trunk's centre of mass, long axes along the body;
!>   back contact under the upper trunk's centre of mass (shoulder blades).
!> Radii of gyration: de Leva's sagittal radius is about the anteroposterior
!> axis (z here), the transverse one about the mediolateral axis (y), the
!> longitudinal one about the segment's long axis (x; for the feet, which
!> point up, z).
!> Transcription caveats (appendix I): the female head mass is taken as the
!> published 6.68 %; the female shares then sum to 99.99 %, so every share is
!> divided by the table's sum (the body weighs exactly the given mass). The
!> female foot's longitudinal radius is 13.9 % (the 12.4 % of some copies
!> repeats the male value).
module rider_body
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_real
  implicit none (type, external)
  private
  public :: body_params_t, rigid_body_t, rider_body_t, build_rider_body, check_body_params, add_segment
  public :: segment_t, de_leva_segment, reference_height, sex_name
  public :: SEX_MALE, SEX_FEMALE
  public :: SEG_HEAD_NECK, SEG_UPPER_TRUNK, SEG_MIDDLE_TRUNK, SEG_LOWER_TRUNK, SEG_UPPER_ARM, SEG_FOREARM, &
    SEG_HAND, SEG_THIGH, SEG_SHANK, SEG_FOOT, N_SEGMENTS

  integer, parameter :: SEX_MALE = 1, SEX_FEMALE = 2
  integer, parameter :: SEG_HEAD_NECK = 1, SEG_UPPER_TRUNK = 2, SEG_MIDDLE_TRUNK = 3, SEG_LOWER_TRUNK = 4, &
    SEG_UPPER_ARM = 5, SEG_FOREARM = 6, SEG_HAND = 7, SEG_THIGH = 8, SEG_SHANK = 9, SEG_FOOT = 10, &
    N_SEGMENTS = 10

  !> One row of de Leva (1996) table 4 for the reference subject.
  type :: segment_t
    real(wp) :: mass_percent = 0        ! % of body mass
    real(wp) :: com_percent = 0         ! % of the length from the first end point
    real(wp) :: gyration_percent(3) = 0 ! % of the length: sagittal, transverse, longitudinal
    real(wp) :: length = 0              ! m
  end type segment_t

  !> Reference subjects (m): male 73.0 kg, 1.741 m; female 61.9 kg, 1.735 m.
  real(wp), parameter :: reference_heights(2) = [1.741_wp, 1.735_wp]

  ! de Leva (1996) table 4 (METHOD-PART2 appendix I), rows in the order of
  ! the SEG_ constants: mass %, CoM %, r_sag %, r_trans %, r_long %, length m.
  real(wp), parameter :: male_table(6, N_SEGMENTS) = reshape([ &
    6.94_wp, 50.02_wp, 30.3_wp, 31.5_wp, 26.1_wp, 0.2429_wp, &    ! head + neck (vertex - C7)
    15.96_wp, 29.99_wp, 71.6_wp, 45.4_wp, 65.9_wp, 0.1707_wp, &   ! upper trunk (suprasternale - xiphion)
    16.33_wp, 45.02_wp, 48.2_wp, 38.3_wp, 46.8_wp, 0.2155_wp, &   ! middle trunk (xiphion - omphalion)
    11.17_wp, 61.15_wp, 61.5_wp, 55.1_wp, 58.7_wp, 0.1457_wp, &   ! lower trunk (omphalion - mid-hip)
    2.71_wp, 57.72_wp, 28.5_wp, 26.9_wp, 15.8_wp, 0.2817_wp, &    ! upper arm
    1.62_wp, 45.74_wp, 27.6_wp, 26.5_wp, 12.1_wp, 0.2689_wp, &    ! forearm
    0.61_wp, 79.00_wp, 62.8_wp, 51.3_wp, 40.1_wp, 0.0862_wp, &    ! hand
    14.16_wp, 40.95_wp, 32.9_wp, 32.9_wp, 14.9_wp, 0.4222_wp, &   ! thigh
    4.33_wp, 44.59_wp, 25.5_wp, 24.9_wp, 10.3_wp, 0.4340_wp, &    ! shank
    1.37_wp, 44.15_wp, 25.7_wp, 24.5_wp, 12.4_wp, 0.2581_wp], &   ! foot (heel - toe tip)
    [6, N_SEGMENTS])
  real(wp), parameter :: female_table(6, N_SEGMENTS) = reshape([ &
    6.68_wp, 48.41_wp, 27.1_wp, 29.5_wp, 26.1_wp, 0.2437_wp, &
    15.45_wp, 20.77_wp, 74.6_wp, 50.2_wp, 71.8_wp, 0.1425_wp, &
    14.65_wp, 45.12_wp, 43.3_wp, 35.4_wp, 41.5_wp, 0.2053_wp, &
    12.47_wp, 49.20_wp, 43.3_wp, 40.2_wp, 44.4_wp, 0.1815_wp, &
    2.55_wp, 57.54_wp, 27.8_wp, 26.0_wp, 14.8_wp, 0.2751_wp, &
    1.38_wp, 45.59_wp, 26.1_wp, 25.7_wp, 9.4_wp, 0.2643_wp, &
    0.56_wp, 74.74_wp, 53.1_wp, 45.4_wp, 33.5_wp, 0.0780_wp, &
    14.78_wp, 36.12_wp, 36.9_wp, 36.4_wp, 16.2_wp, 0.3685_wp, &
    4.81_wp, 44.16_wp, 27.1_wp, 26.7_wp, 9.3_wp, 0.4323_wp, &
    1.29_wp, 40.14_wp, 29.9_wp, 27.9_wp, 13.9_wp, 0.2283_wp], &
    [6, N_SEGMENTS])

  !> The rider as described by the user (docs/rider.md, &rider).
  type :: body_params_t
    real(wp) :: mass = 68.5_wp          ! kg (thesis table 4.10)
    real(wp) :: height = 1.78_wp        ! m (thesis table 4.10)
    real(wp) :: com_height = 0.075_wp   ! m, segment centres of mass above the slide (table 4.10)
    integer :: sex = SEX_MALE           ! which de Leva table
  end type body_params_t

  !> Mass, centre of mass and inertia about it, in the body's frame.
  type :: rigid_body_t
    real(wp) :: mass = 0                ! kg
    real(wp) :: com(3) = 0              ! m
    real(wp) :: inertia(3, 3) = 0       ! kg m^2
  end type rigid_body_t

  type :: rider_body_t
    type(rigid_body_t) :: pelvis        ! in P
    type(rigid_body_t) :: legs          ! in L
    type(rigid_body_t) :: trunk         ! in T
    real(wp) :: hip(3) = 0              ! m, hip joint centre in P
    real(wp) :: heel(3) = 0             ! m, heel contact in L
    real(wp) :: back(3) = 0             ! m, back contact in T
  end type rider_body_t

  ! what build_rider_body accepts (docs/rider.md)
  real(wp), parameter :: mass_range(2) = [10.0_wp, 300.0_wp]      ! kg
  real(wp), parameter :: height_range(2) = [0.5_wp, 2.5_wp]       ! m
  real(wp), parameter :: com_height_range(2) = [0.0_wp, 0.5_wp]   ! m, lower end excluded

contains

  pure function sex_name(sex) result(name)
    integer, intent(in) :: sex
    character(len=:), allocatable :: name
    name = merge('male  ', 'female', sex == SEX_MALE)
    name = trim(name)
  end function sex_name

  pure real(wp) function reference_height(sex)
    integer, intent(in) :: sex
    reference_height = reference_heights(sex)
  end function reference_height

  !> Segment `k` (SEG_ constant) of de Leva's table for `sex`, unscaled.
  pure function de_leva_segment(sex, k) result(s)
    integer, intent(in) :: sex, k
    type(segment_t) :: s
    real(wp) :: row(6)
    if (sex == SEX_MALE) then
      row = male_table(:, k)
    else
      row = female_table(:, k)
    end if
    s%mass_percent = row(1)
    s%com_percent = row(2)
    s%gyration_percent = row(3:5)
    s%length = row(6)
  end function de_leva_segment

  !> Checks the description; the message names the variable (as in &rider).
  subroutine check_body_params(p, status)
    type(body_params_t), intent(in) :: p
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. (p%mass >= mass_range(1) .and. p%mass <= mass_range(2))) then
      call set_status(status, STATUS_INVALID_INPUT, 'mass = '//format_real(p%mass)//': must lie in ['// &
                      format_real(mass_range(1))//', '//format_real(mass_range(2))//'] kg')
    else if (.not. (p%height >= height_range(1) .and. p%height <= height_range(2))) then
      call set_status(status, STATUS_INVALID_INPUT, 'height = '//format_real(p%height)//': must lie in ['// &
                      format_real(height_range(1))//', '//format_real(height_range(2))//'] m')
    else if (.not. (p%com_height > com_height_range(1) .and. p%com_height <= com_height_range(2))) then
      call set_status(status, STATUS_INVALID_INPUT, 'com_height = '//format_real(p%com_height)// &
                      ': must lie in (0, '//format_real(com_height_range(2))//'] m')
    else if (p%sex /= SEX_MALE .and. p%sex /= SEX_FEMALE) then
      call set_status(status, STATUS_INVALID_INPUT, 'sex: must be male or female')
    end if
  end subroutine check_body_params

  !> The three bodies, the hip and the two closing contacts (see the header).
  subroutine build_rider_body(p, body, status)
    type(body_params_t), intent(in) :: p
    type(rider_body_t), intent(out) :: body
    type(status_t), intent(inout) :: status
    type(segment_t) :: seg(N_SEGMENTS)
    real(wp) :: scale, shares, length(N_SEGMENTS), mass(N_SEGMENTS), h, x_hip, l_leg, &
      x_omphalion, x_xiphion, x_suprasternale, x_upper
    integer :: k

    call check_body_params(p, status)
    if (.not. status%ok()) return
    do k = 1, N_SEGMENTS
      seg(k) = de_leva_segment(p%sex, k)
    end do
    scale = p%height/reference_heights(p%sex)
    length = seg%length*scale
    shares = seg(SEG_HEAD_NECK)%mass_percent + seg(SEG_UPPER_TRUNK)%mass_percent + &
             seg(SEG_MIDDLE_TRUNK)%mass_percent + seg(SEG_LOWER_TRUNK)%mass_percent + &
             2*(seg(SEG_UPPER_ARM)%mass_percent + seg(SEG_FOREARM)%mass_percent + seg(SEG_HAND)%mass_percent + &
                seg(SEG_THIGH)%mass_percent + seg(SEG_SHANK)%mass_percent + seg(SEG_FOOT)%mass_percent)
    mass = seg%mass_percent/shares*p%mass
    h = p%com_height

    ! pelvis: the lower trunk, centre of mass over the contact
    x_hip = (1 - seg(SEG_LOWER_TRUNK)%com_percent/100)*length(SEG_LOWER_TRUNK)
    body%hip = [x_hip, 0.0_wp, h]
    call add_segment(body%pelvis, mass(SEG_LOWER_TRUNK), [0.0_wp, 0.0_wp, h], &
                     own_inertia(mass(SEG_LOWER_TRUNK), length(SEG_LOWER_TRUNK), seg(SEG_LOWER_TRUNK), .false.))

    ! legs from the hip along +x; two of each segment, on the axis (crossed)
    l_leg = length(SEG_THIGH) + length(SEG_SHANK)
    call add_segment(body%legs, 2*mass(SEG_THIGH), [seg(SEG_THIGH)%com_percent/100*length(SEG_THIGH), 0.0_wp, &
                     0.0_wp], 2*own_inertia(mass(SEG_THIGH), length(SEG_THIGH), seg(SEG_THIGH), .false.))
    call add_segment(body%legs, 2*mass(SEG_SHANK), [length(SEG_THIGH) + seg(SEG_SHANK)%com_percent/100* &
                     length(SEG_SHANK), 0.0_wp, 0.0_wp], &
                     2*own_inertia(mass(SEG_SHANK), length(SEG_SHANK), seg(SEG_SHANK), .false.))
    call add_segment(body%legs, 2*mass(SEG_FOOT), [l_leg, 0.0_wp, 0.0_wp], &
                     2*own_inertia(mass(SEG_FOOT), length(SEG_FOOT), seg(SEG_FOOT), .true.))
    body%heel = [l_leg, 0.0_wp, -h]

    ! trunk from the hip along -x
    x_omphalion = -length(SEG_LOWER_TRUNK)
    x_xiphion = x_omphalion - length(SEG_MIDDLE_TRUNK)
    x_suprasternale = x_xiphion - length(SEG_UPPER_TRUNK)
    x_upper = x_suprasternale + seg(SEG_UPPER_TRUNK)%com_percent/100*length(SEG_UPPER_TRUNK)
    call add_segment(body%trunk, mass(SEG_MIDDLE_TRUNK), [x_xiphion + seg(SEG_MIDDLE_TRUNK)%com_percent/100* &
                     length(SEG_MIDDLE_TRUNK), 0.0_wp, 0.0_wp], &
                     own_inertia(mass(SEG_MIDDLE_TRUNK), length(SEG_MIDDLE_TRUNK), seg(SEG_MIDDLE_TRUNK), .false.))
    call add_segment(body%trunk, mass(SEG_UPPER_TRUNK), [x_upper, 0.0_wp, 0.0_wp], &
                     own_inertia(mass(SEG_UPPER_TRUNK), length(SEG_UPPER_TRUNK), seg(SEG_UPPER_TRUNK), .false.))
    call add_segment(body%trunk, mass(SEG_HEAD_NECK), [x_suprasternale - (1 - seg(SEG_HEAD_NECK)%com_percent/100)* &
                     length(SEG_HEAD_NECK), 0.0_wp, 0.0_wp], &
                     own_inertia(mass(SEG_HEAD_NECK), length(SEG_HEAD_NECK), seg(SEG_HEAD_NECK), .false.))
    do k = SEG_UPPER_ARM, SEG_HAND
      call add_segment(body%trunk, 2*mass(k), [x_upper, 0.0_wp, 0.0_wp], &
                       2*own_inertia(mass(k), length(k), seg(k), .false.))
    end do
    body%back = [x_upper, 0.0_wp, -h]
  end subroutine build_rider_body

  !> Principal inertia of one segment about its centre of mass: long axis
  !> along x (sagittal axis z), or along z for the feet (sagittal axis x).
  pure function own_inertia(mass, length, seg, long_along_z) result(inertia)
    real(wp), intent(in) :: mass, length
    type(segment_t), intent(in) :: seg
    logical, intent(in) :: long_along_z
    real(wp) :: inertia(3, 3)
    real(wp) :: r(3)   ! m: sagittal, transverse, longitudinal radius of gyration
    r = seg%gyration_percent/100*length
    inertia = 0
    inertia(2, 2) = mass*r(2)**2
    if (long_along_z) then
      inertia(1, 1) = mass*r(1)**2
      inertia(3, 3) = mass*r(3)**2
    else
      inertia(1, 1) = mass*r(3)**2
      inertia(3, 3) = mass*r(1)**2
    end if
  end function own_inertia

  !> Adds a point-like segment (mass at `com` with its own inertia about
  !> `com`) to `b`: new centre of mass, inertia by the parallel-axis theorem.
  pure subroutine add_segment(b, mass, com, inertia)
    type(rigid_body_t), intent(inout) :: b
    real(wp), intent(in) :: mass, com(3), inertia(3, 3)
    real(wp) :: total, c(3), d_old(3), d_new(3)
    total = b%mass + mass
    c = (b%mass*b%com + mass*com)/total
    d_old = b%com - c
    d_new = com - c
    b%inertia = b%inertia + steiner(b%mass, d_old) + inertia + steiner(mass, d_new)
    b%mass = total
    b%com = c
  end subroutine add_segment

  !> m (|d|^2 E - d d^T): the parallel-axis term.
  pure function steiner(mass, d) result(s)
    real(wp), intent(in) :: mass, d(3)
    real(wp) :: s(3, 3)
    integer :: i
    s = -mass*spread(d, 2, 3)*spread(d, 1, 3)
    do i = 1, 3
      s(i, i) = s(i, i) + mass*dot_product(d, d)
    end do
  end function steiner
end module rider_body
