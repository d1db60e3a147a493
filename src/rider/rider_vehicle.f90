!> Riders beyond the body slide (issue 26 point 2): a mat with a rider lying
!> prone head first, a rider sitting up, a single or double ring with 1-2
!> riders, a raft with 1-4 riders, each one rigid body on the slide at two
!> contacts, ridden as the sled of kinetostatics_models (&sled vehicle).
!> Every vehicle comes from data, not code of its own: persons from de
!> Leva's segments (rider_body) in a posture, at one size `scale`; rings and
!> rafts from torus geometry; the mat a box. The choices and their sources
!> are in docs/vehicles.md; keep the two in step.
!>
!> Vehicle frame V (m): origin at the rear contact on the slide, x towards
!> the front contact (down the slide when phi0 = 0), z the slide's normal on
!> the vehicle's side, y = z x x. Both contacts lie on the slide (z = 0).
!>
!> A person of size s (`scales(k)` for rider k): height s H_ref, H_ref =
!> 1.741 m, mass s^3 M_ref, M_ref = 73.0 kg (de Leva's male reference
!> subject, scaled isometrically), segment centres of mass h = 0.075 m
!> (H/1.78 m) above the surface the person lies on (thesis table 4.10,
!> scaled). The person is rigid: the three bodies of rider_body joined at the
!> hip, either straight (lying) or with the trunk turned up by 90 degrees
!> (sitting up).
!>
!> The vehicle's own parts (the mat's sizes and mass, the rings' and the
!> raft's torus radii and masses, the raft's floor) are the vehicle_t's, from
!> input (&sled mat_length, ..., raft_floor); its defaults are those of
!> common commercial mats and tubes (docs/vehicles.md, "The input").
module rider_vehicle
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_INTERNAL
  use base_text, only: format_real, format_integer, format_vector
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_slide_query, only: slide_surface_t, slide_bottom_v
  use base_vector, only: cross
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_recorder, only: mechanism_series_t
  use rider_extremes, only: felt_acceleration
  use kinetostatics_models, only: sled_description_t, build_sled_model
  use rider_body, only: body_params_t, rigid_body_t, rider_body_t, build_rider_body, add_segment, SEX_MALE
  use rider_drag, only: water_properties_t
  use rider_water_drag, only: new_water_drag, in_water_roots
  use water_field, only: water_field_t
  use kinetostatics_impact, only: impact_law_t
  implicit none (type, external)
  private
  public :: vehicle_t, vehicle_body_t, vehicle_body, check_vehicle, build_vehicle_model, vehicle_kind_index
  public :: riders_allowed, vehicle_kinds, vehicle_problem, max_riders
  public :: VEHICLE_BAR, VEHICLE_MAT, VEHICLE_SITTING, VEHICLE_RING, VEHICLE_DOUBLE_RING, VEHICLE_RAFT
  public :: person_reference_height, person_reference_mass, scale_range, vehicle_ride_figures, torus
  public :: narrowest_section, width_tolerance

  integer, parameter :: VEHICLE_BAR = 1, VEHICLE_MAT = 2, VEHICLE_SITTING = 3, VEHICLE_RING = 4, &
    VEHICLE_DOUBLE_RING = 5, VEHICLE_RAFT = 6
  character(len=*), parameter :: vehicle_kinds(6) = [character(len=11) :: 'bar', 'mat', 'sitting', 'ring', &
    'double_ring', 'raft']
  !> how many riders each kind carries: fewest, most
  integer, parameter :: rider_counts(2, 6) = reshape([0, 0, 1, 1, 1, 1, 1, 1, 1, 2, 1, 4], [2, 6])

  !> de Leva (1996)'s male reference subject (Zatsiorsky's sample)
  real(wp), parameter :: person_reference_height = 1.741_wp   ! m
  real(wp), parameter :: person_reference_mass = 73.0_wp      ! kg
  !> scale 0.6: 1.04 m, 15.8 kg (a 5th-percentile child of about 5 years);
  !> 1.1: 1.92 m, 97 kg (beyond a 95th-percentile adult man)
  real(wp), parameter :: scale_range(2) = [0.6_wp, 1.1_wp]
  !> the most riders a vehicle carries (a raft's)
  integer, parameter :: max_riders = 4

  !> The water's drag on a vehicle (docs/vehicles.md, "In the water"): the
  !> rider's drag model (rider_drag) on a sphere at each contact, the
  !> sphere standing for what the vehicle wets there: a tube's cross-section
  !> (its radius r, from input) under a ring or a raft, the body-slide
  !> rider's pelvis and back spheres (0.5 m, thesis 4.3: &rider
  !> drag_radius's defaults, fixed here) under a mat and a seat, its heels'
  !> (0.05 m) under a sitting rider's heels.
  real(wp), parameter :: body_sphere = 0.5_wp, heel_sphere = 0.05_wp   ! m

  !> a person's width at scale 1 (shoulders, biacromial breadth of an adult
  !> man, about 0.40 m; de Leva's segments have no widths), scaled by `scale`
  real(wp), parameter :: shoulder_breadth = 0.40_wp                ! m

  !> The width check (narrowest_section): the slide's sections every
  !> section_step of arc length, each at section_points points across; a
  !> vehicle wider than a section by more than width_tolerance (the
  !> sampling: a circle's width is found to r (1 - cos 1 deg) = 1.5e-4 r)
  !> does not fit.
  real(wp), parameter :: section_step = 0.25_wp    ! m
  integer, parameter :: section_points = 181
  real(wp), parameter :: width_tolerance = 1e-3_wp   ! m

  !> A vehicle as the input gives it (&sled vehicle, riders, scale, scales
  !> and the parts' values): the one description every ride of it takes.
  type :: vehicle_t
    integer :: kind = VEHICLE_BAR     ! VEHICLE_BAR: the plain bar of &sled, no vehicle
    integer :: riders = 1
    !> each rider's size (see the header): rider k's scales(k), k <= riders
    !> (a double ring's first rider in the front ring; a raft's first at
    !> the rear, the others on round it)
    real(wp) :: scales(max_riders) = 1
    !> in the computed water (&sled water = 'computed', the default for a
    !> vehicle) or dry (water = 'dry'); the bar rides dry
    logical :: in_water = .false.
    type(water_properties_t) :: water
    !> a lift-off opens the contact and the vehicle flies (&sled may_fly;
    !> rider_vehicle_flight), landing by `landing`'s law
    logical :: may_fly = .false.
    type(impact_law_t) :: landing
    !> The vehicle's own parts (docs/vehicles.md, "The input"; the defaults
    !> are io_declarations_multibody's, chosen, not measured: racing mats
    !> about 1 m, 1-2 kg; single tubes 1.1-1.2 m across, 6-8 kg; four-seat
    !> round rafts about 2 m, 25-35 kg). The mat: length (the contacts'
    !> distance), width, thickness (m), a solid box of mass mat_mass (kg).
    real(wp) :: mat_size(3) = [1.0_wp, 0.6_wp, 0.04_wp]
    real(wp) :: mat_mass = 1.5_wp
    !> a ring's thin-walled torus: R to the tube's centre, r the tube's (m),
    !> 1.2 m outside; the mass of each torus of a single or double ring (kg)
    real(wp) :: ring_radii(2) = [0.45_wp, 0.15_wp]
    real(wp) :: ring_mass = 7.0_wp
    !> the raft's torus (R, r; m), its mass with the floor (kg) and the
    !> height of the floor its riders sit on (m)
    real(wp) :: raft_radii(2) = [0.75_wp, 0.22_wp]
    real(wp) :: raft_mass = 30.0_wp
    real(wp) :: raft_floor = 0.03_wp
  end type vehicle_t

  !> The vehicle with its riders as one rigid body, in V.
  type :: vehicle_body_t
    type(rigid_body_t) :: body        ! all of it: mass, centre of mass and inertia about it
    real(wp) :: length = 0            ! m, rear to front contact (along x)
    real(wp) :: width = 0             ! m, across (along y): the widest of vehicle and riders
    real(wp) :: vehicle_mass = 0      ! kg, the vehicle without riders (0: a rider sitting on the slide)
    real(wp) :: drag_radius(2) = 0    ! m, the water drag's sphere at the rear and the front contact
  end type vehicle_body_t

contains

  !> How many riders a vehicle of `kind` carries, in words: 'a bar carries
  !> no riders', 'a ring carries 1 rider only', 'a raft carries 1 to 4 riders'.
  function riders_allowed(kind) result(text)
    integer, intent(in) :: kind
    character(len=:), allocatable :: text
    text = 'a '//trim(vehicle_kinds(kind))//' carries '
    if (rider_counts(2, kind) == 0) then
      text = text//'no riders'
    else if (rider_counts(1, kind) == rider_counts(2, kind)) then
      text = text//format_integer(rider_counts(1, kind))//' rider'//trim(merge('s', ' ', rider_counts(1, kind) > 1))// &
             ' only'
    else
      text = text//format_integer(rider_counts(1, kind))//' to '//format_integer(rider_counts(2, kind))//' riders'
    end if
  end function riders_allowed

  !> The index of the kind called `name` in vehicle_kinds, 0 if none.
  pure integer function vehicle_kind_index(name)
    character(len=*), intent(in) :: name
    vehicle_kind_index = findloc(vehicle_kinds, name, dim=1)
  end function vehicle_kind_index

  !> Refuses a vehicle its kind cannot carry or whose parts cannot be; the
  !> message names the variable (vehicle_problem).
  subroutine check_vehicle(v, status)
    type(vehicle_t), intent(in) :: v
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: variable, value, allowed
    if (.not. status%ok()) return
    if (v%kind < 1 .or. v%kind > size(vehicle_kinds)) then
      call set_status(status, STATUS_INVALID_INPUT, 'vehicle: not a kind of vehicle')
      return
    end if
    call vehicle_problem(v, variable, value, allowed)
    if (len(variable) > 0) call set_status(status, STATUS_INVALID_INPUT, variable//' = '//value//': '//allowed)
  end subroutine check_vehicle

  !> The first value of vehicle `v` (a kind of vehicle_kinds) that its kind
  !> cannot carry or that cannot be: the variable as &sled names it, its
  !> value and what is allowed in words; variable = '' if none. The parts of
  !> other kinds are not looked at (the reader refuses them given).
  subroutine vehicle_problem(v, variable, value, allowed)
    type(vehicle_t), intent(in) :: v
    character(len=:), allocatable, intent(out) :: variable, value, allowed
    integer :: k
    variable = ''
    value = ''
    allowed = ''
    if (v%kind == VEHICLE_BAR) return
    if (v%riders < rider_counts(1, v%kind) .or. v%riders > rider_counts(2, v%kind)) then
      call found('riders', format_integer(v%riders), riders_allowed(v%kind))
      return
    end if
    do k = 1, v%riders
      if (.not. (v%scales(k) >= scale_range(1) .and. v%scales(k) <= scale_range(2))) then
        call found('scales('//format_integer(k)//')', format_real(v%scales(k)), 'must lie in ['// &
                   format_real(scale_range(1))//', '//format_real(scale_range(2))//']')
        return
      end if
    end do
    select case (v%kind)
    case (VEHICLE_MAT)
      if (.not. all(v%mat_size > 0)) then
        call found('mat_length, mat_width, mat_thickness', format_vector(v%mat_size, brackets=.false.), &
                   'each must be > 0 (m)')
      else if (.not. v%mat_mass > 0) then
        call found('mat_mass', format_real(v%mat_mass), 'must be > 0 (kg)')
      end if
    case (VEHICLE_RING, VEHICLE_DOUBLE_RING)
      call torus_problem('ring', v%ring_radii, v%ring_mass)
    case (VEHICLE_RAFT)
      call torus_problem('raft', v%raft_radii, v%raft_mass)
      if (len(variable) == 0 .and. .not. (v%raft_floor >= 0 .and. v%raft_floor <= 2*v%raft_radii(2))) &
        call found('raft_floor', format_real(v%raft_floor), 'must lie in [0, 2 r] = [0, '// &
                   format_real(2*v%raft_radii(2))//'] m: within the tube''s height')
    end select
  contains
    subroutine found(name, text, words)
      character(len=*), intent(in) :: name, text, words
      variable = name
      value = text
      allowed = words
    end subroutine found
    !> a torus of radii (R, r) is a ring only with 0 < r < R
    subroutine torus_problem(part, radii, mass)
      character(len=*), intent(in) :: part
      real(wp), intent(in) :: radii(2), mass
      if (.not. (radii(2) > 0 .and. radii(2) < radii(1))) then
        call found(part//'_radii', format_vector(radii, brackets=.false.), 'the tube''s radius r (the second) '// &
                   'must be > 0 and less than R (the first, from the '//part//'''s centre to the tube''s centre)')
      else if (.not. mass > 0) then
        call found(part//'_mass', format_real(mass), 'must be > 0 (kg)')
      end if
    end subroutine torus_problem
  end subroutine vehicle_problem


  !> The vehicle `v` with its riders as one rigid body in V (see the header).
  subroutine vehicle_body(v, vb, status)
    type(vehicle_t), intent(in) :: v
    type(vehicle_body_t), intent(out) :: vb
    type(status_t), intent(inout) :: status
    type(rigid_body_t) :: lying(max_riders), sitting(max_riders)
    real(wp) :: heel(max_riders), psi, centre(3)
    integer :: k

    call check_vehicle(v, status)
    if (.not. status%ok()) return
    if (v%kind == VEHICLE_BAR) then
      call set_status(status, STATUS_INVALID_INPUT, 'vehicle = ''bar'': the plain bar has no vehicle body')
      return
    end if
    do k = 1, v%riders
      call person(v%scales(k), lying(k), sitting(k), heel(k), status)
      if (.not. status%ok()) return
    end do
    select case (v%kind)
    case (VEHICLE_MAT)
      ! the box, then the rider prone, head first (turned by pi about z),
      ! lying on it with the centre of mass over the mat's middle
      associate (a => v%mat_size)
        call add_body(vb%body, rigid_body_t(v%mat_mass, [a(1)/2, 0.0_wp, a(3)/2], box_inertia(v%mat_mass, a)), &
                      0.0_wp, [0.0_wp, 0.0_wp, 0.0_wp])
        call add_body(vb%body, lying(1), pi, [a(1)/2 + lying(1)%com(1), 0.0_wp, a(3)])
        vb%length = a(1)
        vb%width = max(a(2), v%scales(1)*shoulder_breadth)
      end associate
      vb%vehicle_mass = v%mat_mass
      vb%drag_radius = body_sphere
    case (VEHICLE_SITTING)
      ! on the slide itself: seat (the pelvis contact) behind, heels in front
      call add_body(vb%body, sitting(1), 0.0_wp, [0.0_wp, 0.0_wp, 0.0_wp])
      vb%length = heel(1)
      vb%width = v%scales(1)*shoulder_breadth
      vb%drag_radius = [body_sphere, heel_sphere]
    case (VEHICLE_RING)
      associate (r1 => v%ring_radii(1), r2 => v%ring_radii(2))
        call add_body(vb%body, torus(v%ring_mass, v%ring_radii), 0.0_wp, [r1, 0.0_wp, r2])
        call add_body(vb%body, sitting(1), 0.0_wp, [r1, 0.0_wp, r2])
        vb%length = 2*r1
        vb%width = 2*(r1 + r2)
        vb%drag_radius = r2
      end associate
      vb%vehicle_mass = v%ring_mass
    case (VEHICLE_DOUBLE_RING)
      ! two rings in line, touching (centres 2 (R + r) apart); the first
      ! rider in the front ring, the second in the rear one
      associate (r1 => v%ring_radii(1), r2 => v%ring_radii(2))
        centre = [r1, 0.0_wp, r2]
        call add_body(vb%body, torus(v%ring_mass, v%ring_radii), 0.0_wp, centre)
        if (v%riders == 2) call add_body(vb%body, sitting(2), 0.0_wp, centre)
        centre(1) = r1 + 2*(r1 + r2)
        call add_body(vb%body, torus(v%ring_mass, v%ring_radii), 0.0_wp, centre)
        call add_body(vb%body, sitting(1), 0.0_wp, centre)
        vb%length = 4*r1 + 2*r2
        vb%width = 2*(r1 + r2)
        vb%drag_radius = r2
      end associate
      vb%vehicle_mass = 2*v%ring_mass
    case (VEHICLE_RAFT)
      ! riders evenly round the floor, backs to the tube, legs to the
      ! middle; the first at the rear facing forward
      associate (r1 => v%raft_radii(1), r2 => v%raft_radii(2))
        call add_body(vb%body, torus(v%raft_mass, v%raft_radii), 0.0_wp, [r1, 0.0_wp, r2])
        do k = 1, v%riders
          psi = pi + 2*pi*(k - 1)/v%riders
          call add_body(vb%body, sitting(k), psi + pi, [r1 + (r1 - r2)*cos(psi), (r1 - r2)*sin(psi), v%raft_floor])
        end do
        vb%length = 2*r1
        vb%width = 2*(r1 + r2)
        vb%drag_radius = r2
      end associate
      vb%vehicle_mass = v%raft_mass
    end select
  end subroutine vehicle_body

  !> The sled of `d` with the body of vehicle `v` in place of its bar (its
  !> length, mass, inertia and centre of mass), on `surface`, and its start
  !> (build_sled_model). Given `water` (the computed water on `surface`),
  !> the water's drag at both contacts ('rear_water_drag',
  !> 'front_water_drag': rider_water_drag with the vehicle's spheres and
  !> v%water), each on where its contact starts between the water's edges;
  !> the laws point at `water` (no copy), which outlives m.
  !> lift, open, solve_yaw, free_roll: a flight build (build_sled;
  !> rider_vehicle_flight).
  subroutine build_vehicle_model(v, d, surface, m, q0, qd0, status, water, lift, open, solve_yaw, free_roll)
    type(vehicle_t), intent(in) :: v
    type(sled_description_t), intent(in) :: d
    class(surface_t), intent(in) :: surface
    type(mechanism_t), intent(out) :: m
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(inout) :: status
    type(water_field_t), intent(in), optional, target :: water
    logical, intent(in), optional :: lift, open(2), solve_yaw, free_roll
    character(len=*), parameter :: contacts(2) = [character(len=5) :: 'rear', 'front']
    character(len=*), parameter :: u_names(2) = [character(len=2) :: 'u', 'u2']
    character(len=*), parameter :: v_names(2) = [character(len=2) :: 'v', 'v2']
    type(sled_description_t) :: carried
    type(vehicle_body_t) :: vb
    real(wp) :: g(2)
    integer :: k, su, sv
    if (.not. status%ok()) return
    carried = d
    if (v%kind /= VEHICLE_BAR) then
      call vehicle_body(v, vb, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'vehicle '''//trim(vehicle_kinds(v%kind))//'''')
        return
      end if
      carried%params%length = vb%length
      carried%params%mass = vb%body%mass
      carried%params%inertia = vb%body%inertia
      carried%params%centre_offset = vb%body%com - [vb%length/2, 0.0_wp, 0.0_wp]
    end if
    if (.not. present(water)) then
      call build_sled_model(carried, surface, m, q0, qd0, status, lift=lift, open=open, solve_yaw=solve_yaw, &
                            free_roll=free_roll)
      return
    end if
    if (v%kind == VEHICLE_BAR) then
      call set_status(status, STATUS_INTERNAL, 'the water''s drag acts on a vehicle''s contacts, not on the bar')
      return
    end if
    call build_sled_model(carried, surface, m, q0, qd0, status, finish=.false., lift=lift, open=open, &
                          solve_yaw=solve_yaw, free_roll=free_roll)
    if (.not. status%ok()) return
    do k = 1, 2
      su = m%scalar_index(trim(u_names(k)))
      sv = m%scalar_index(trim(v_names(k)))
      call in_water_roots(water, m%scalars(su)%q, m%scalars(sv)%q, g)
      call m%add_law(new_water_drag(trim(contacts(k))//'_water_drag', m%contact_index(trim(contacts(k))), su, sv, &
                                    vb%drag_radius(k), v%water, water, all(g > 0)))
    end do
    call m%finalize(status)
  end subroutine build_vehicle_model

  !> The ride figures of a vehicle's run at each of its records `s`
  !> (docs/vehicles.md, "What the run reports"): the speed of the centre of
  !> mass (m/s) and the felt acceleration there, (a_c - g)/|g| along the
  !> vehicle's x (forward), y (left) and z (the normal) axes (g), from the
  !> vehicle's mechanism `m` evaluated at each record's state, its closure
  !> started from the record's dependent coordinates and its force laws on
  !> or off as they were at that record (the water's drag switches during a
  !> ride: the workspace holds the run's last state; restored on return).
  subroutine vehicle_ride_figures(m, work, s, speed, felt, status)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    type(mechanism_series_t), intent(in) :: s
    real(wp), allocatable, intent(out) :: speed(:), felt(:, :)
    type(status_t), intent(inout) :: status
    real(wp) :: residual, arm(3), acceleration(3), gravity(3), com(3), mass, inertia(3, 3)
    logical :: run_active(m%n_laws)
    integer :: i, k, e, frame
    allocate (speed(s%n), felt(3, s%n))
    speed = 0
    felt = 0
    frame = 0
    do e = 1, m%n_elements
      if (m%elements(e)%e%mass_frame() == 0) cycle   ! the element carries no mass
      frame = m%elements(e)%e%mass_frame()
      call m%elements(e)%e%mass_properties(mass, com, inertia, gravity)
    end do
    if (frame == 0) then
      call set_status(status, STATUS_INTERNAL, 'vehicle figures: the mechanism has no body')
      return
    end if
    call m%prepare_workspace(work)
    run_active = [(work%laws(k)%law%active, k = 1, m%n_laws)]
    do i = 1, s%n
      do k = 1, m%r
        work%scalars(m%beta(k))%q = s%beta(k, i)
      end do
      do k = 1, m%n_laws
        work%laws(k)%law%active = s%law_active(k, i) > 0.5_wp
      end do
      work%warm = .false.
      work%converged = .false.
      call m%evaluate(work, s%time(i), s%q(:, i), s%qd(:, i), residual, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'vehicle figures at t = '//format_real(s%time(i))//' s')
        exit
      end if
      associate (p => work%frames(frame))
        arm = matmul(p%rot, com)
        speed(i) = norm2(p%v + cross(p%omega, arm))
        acceleration = p%a + cross(p%alpha, arm) + cross(p%omega, cross(p%omega, arm))
        felt(:, i) = felt_acceleration(acceleration, gravity, p%rot)
      end associate
    end do
    do k = 1, m%n_laws
      work%laws(k)%law%active = run_active(k)
    end do
  end subroutine vehicle_ride_figures

  !> The narrowest section of `surface` (docs/vehicles.md, "Does it fit?"):
  !> the width of each section across its bottom, the extent of its points
  !> along the surface's v tangent at the bottom (v = slide_bottom_v), every
  !> section_step of arc length from the start to the end; `width` the
  !> smallest (m) and `at` its arc length (m). `checked` is false, and
  !> nothing is measured, on a surface that is not a slide (no sections: a
  !> plane, a sphere).
  subroutine narrowest_section(surface, width, at, checked, status)
    class(surface_t), intent(in) :: surface
    real(wp), intent(out) :: width, at
    logical, intent(out) :: checked
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: p
    real(wp) :: u_min, u_max, v_min, v_max, u(1), across(3), v(section_points), section, d(section_points)
    real(wp) :: x(section_points, 1), y(section_points, 1), z(section_points, 1)
    integer :: i, n
    width = huge(1.0_wp)
    at = 0
    checked = .false.
    if (.not. status%ok()) return
    select type (surface)
    class is (slide_surface_t)
      checked = .true.
      call surface%domain(u_min, u_max, v_min, v_max)
      v = [(v_min + (v_max - v_min)*(i - 1)/(section_points - 1), i = 1, section_points)]
      n = max(2, ceiling(surface%length()/section_step) + 1)
      do i = 1, n
        u(1) = u_min + (u_max - u_min)*(i - 1)/(n - 1)
        call surface%evaluate(u(1), slide_bottom_v, 1, p, status)
        ! the section's points at once (a tube evaluates its centreline once)
        if (status%ok()) call surface%points_on_grid(u, v, x, y, z, status)
        if (.not. status%ok()) exit
        across = p%rv/norm2(p%rv)
        d = (x(:, 1) - p%r(1))*across(1) + (y(:, 1) - p%r(2))*across(2) + (z(:, 1) - p%r(3))*across(3)
        section = max(maxval(d), 0.0_wp) - min(minval(d), 0.0_wp)
        if (section < width - 1e-9_wp) then   ! ties: the first
          width = section
          at = surface%arc_length(u(1))
        end if
      end do
      if (.not. status%ok()) call prefix_status(status, 'the width of the slide''s sections')
    end select
  end subroutine narrowest_section

  !> One person of size `scale`, rigid, in the pelvis frame P of rider_body
  !> (origin at the seat on the surface below the pelvis, x towards the feet,
  !> z up): lying straight, and sitting up (the trunk turned by 90 degrees
  !> about y at the hip, head up); `heel` the heels' x, on the surface.
  subroutine person(scale, lying, sitting, heel, status)
    real(wp), intent(in) :: scale
    type(rigid_body_t), intent(out) :: lying, sitting
    real(wp), intent(out) :: heel
    type(status_t), intent(inout) :: status
    type(body_params_t) :: p
    type(rider_body_t) :: rb
    real(wp) :: up(3, 3)
    p%height = scale*person_reference_height
    p%mass = scale**3*person_reference_mass
    p%com_height = 0.075_wp*p%height/1.78_wp
    p%sex = SEX_MALE
    call build_rider_body(p, rb, status)
    if (.not. status%ok()) return
    call add_segment(lying, rb%pelvis%mass, rb%pelvis%com, rb%pelvis%inertia)
    call add_segment(lying, rb%legs%mass, rb%legs%com + rb%hip, rb%legs%inertia)
    sitting = lying
    call add_segment(lying, rb%trunk%mass, rb%trunk%com + rb%hip, rb%trunk%inertia)
    ! about +y by 90 degrees: (x, y, z) -> (z, y, -x), the trunk's -x up
    up = reshape([0.0_wp, 0.0_wp, -1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp], [3, 3])
    call add_segment(sitting, rb%trunk%mass, matmul(up, rb%trunk%com) + rb%hip, &
                     matmul(up, matmul(rb%trunk%inertia, transpose(up))))
    heel = rb%hip(1) + rb%heel(1)
  end subroutine person

  !> Adds `part` (given in its own frame) turned by `psi` about z and moved
  !> by `origin`, to `total`.
  pure subroutine add_body(total, part, psi, origin)
    type(rigid_body_t), intent(inout) :: total
    type(rigid_body_t), intent(in) :: part
    real(wp), intent(in) :: psi, origin(3)
    real(wp) :: turn(3, 3)
    turn = reshape([cos(psi), sin(psi), 0.0_wp, -sin(psi), cos(psi), 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [3, 3])
    call add_segment(total, part%mass, matmul(turn, part%com) + origin, &
                     matmul(turn, matmul(part%inertia, transpose(turn))))
  end subroutine add_body

  !> A thin-walled torus (axis z, centre at its origin): radii(1) = R from
  !> the axis to the tube's centre, radii(2) = r the tube's. Over the shell
  !> (area element ~ R + r cos t): I_z = m (R^2 + 3 r^2/2),
  !> I_x = I_y = m (R^2/2 + 5 r^2/4).
  pure function torus(mass, radii) result(b)
    real(wp), intent(in) :: mass, radii(2)
    type(rigid_body_t) :: b
    b%mass = mass
    b%com = 0
    b%inertia = 0
    b%inertia(1, 1) = mass*(radii(1)**2/2 + 5*radii(2)**2/4)
    b%inertia(2, 2) = b%inertia(1, 1)
    b%inertia(3, 3) = mass*(radii(1)**2 + 3*radii(2)**2/2)
  end function torus

  !> A solid box of sides a(1:3) about its centre.
  pure function box_inertia(mass, a) result(inertia)
    real(wp), intent(in) :: mass, a(3)
    real(wp) :: inertia(3, 3)
    inertia = 0
    inertia(1, 1) = mass*(a(2)**2 + a(3)**2)/12
    inertia(2, 2) = mass*(a(1)**2 + a(3)**2)/12
    inertia(3, 3) = mass*(a(1)**2 + a(2)**2)/12
  end function box_inertia
end module rider_vehicle
