!> The rider as a mechanism (thesis 4.3, (4.27); METHOD-PART2 B.1): the
!> pelvis on a surface joint with its heading (q = [u_B, v_B, phi_B]), legs and
!> trunk on revolutes at the hip (flexion phi_U, tilt phi_O), heels and back
!> held on the slide by a surface joint each and three plane-point conditions
!> in that contact's Darboux frame (dependent [phi_U, u_U, v_U] and
!> [phi_O, u_O, v_O]), the same closure as the sled's front end.
!>
!> Frames (docs/rider.md "Body"): the Darboux frame of each contact has
!> sigma = 1 (z into the tube), alpha_u = 1, alpha_v = 0 (x along r_u, down the
!> slide); the pelvis frame P is the pelvis contact's Darboux frame turned by
!> phi_B about z. Legs turn about -y_P at the hip (positive flexion lifts the
!> heels), the trunk about +y_P (positive tilt lifts the head).
!>
!> The model is built from a description (rider_params_t) and nothing else:
!> no module state, so many riders can be built and run at once.
module rider_model
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use kinetostatics_joints, only: new_rigid_offset, new_revolute, new_prismatic
  use kinetostatics_surface_joint, only: new_surface_joint
  use kinetostatics_measurements, only: new_point_coordinates
  use kinetostatics_mass, only: new_mass_element
  use kinetostatics_mechanism, only: mechanism_t
  use base_spec, only: spec_t
  use kinetostatics_force_law, only: force_law_t, law_place_t
  use kinetostatics_force_law_factory, only: force_law_from_spec, law_spec
  use water_field, only: water_field_t
  use rider_body, only: body_params_t, rigid_body_t, rider_body_t, build_rider_body
  use rider_drag, only: water_properties_t
  use rider_start, only: contact_reach_t, reach_contact, start_parameter
  use rider_water_drag, only: new_water_drag, in_water_roots
  use rider_hip_hold, only: new_hip_hold
  implicit none (type, external)
  private
  public :: rider_params_t, rider_layout_t, build_rider, rider_start_velocity, contact_names
  public :: rider_friction, rider_friction_kind, rider_coulomb_mu, set_rider_mu, rider_default_mu
  public :: CONTACT_PELVIS, CONTACT_HEELS, CONTACT_BACK, N_CONTACTS, flexion_range, tilt_range

  integer, parameter :: CONTACT_PELVIS = 1, CONTACT_HEELS = 2, CONTACT_BACK = 3, N_CONTACTS = 3
  character(len=*), parameter :: contact_names(N_CONTACTS) = [character(len=6) :: 'pelvis', 'heels', 'back']

  !> Joint angles the start search may use (rad): legs' flexion, trunk's
  !> tilt; a flight that swings a limb out of them ends the ride (the free
  !> hip has no stiffness: rider_ride).
  real(wp), parameter :: flexion_range(2) = [-30, 90]*(pi/180)
  real(wp), parameter :: tilt_range(2) = [-30, 90]*(pi/180)

  !> The rider's Coulomb friction coefficient mu_D when no law is given (thesis table 4.8).
  real(wp), parameter :: rider_default_mu = 0.0724419_wp

  !> Everything that defines a rider and its start (docs/rider.md, &rider).
  type :: rider_params_t
    type(body_params_t) :: body
    !> the friction law at each of the three contacts: a kind of the force-law
    !> registry and its parameters (kinetostatics_force_law_factory), 'none'
    !> for none; not set (no kind): Coulomb with mu = rider_default_mu
    !> (rider_friction)
    type(spec_t) :: friction
    logical :: drag = .true.                        ! water drag on the three spheres
    real(wp) :: drag_radius(N_CONTACTS) = [0.5_wp, 0.05_wp, 0.5_wp]   ! m: pelvis, heels, back (thesis 4.3)
    type(water_properties_t) :: water
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]     ! m/s^2
    real(wp) :: u0 = 0.5_wp                         ! m, pelvis start: arc length along the centerline
    real(wp) :: v0 = pi/2                           ! rad (pi/2: the bottom of a tube)
    real(wp) :: heading0 = 0                        ! rad, body axis from x_D (down the slide) towards y_D
    real(wp) :: speed0 = 1                          ! m/s, along the body axis
    logical :: one_sided = .true.                   ! contacts can lift off (the ride stops there)
  end type rider_params_t

  !> Where the rider's pieces sit in the mechanism.
  type :: rider_layout_t
    integer :: contact_frame(N_CONTACTS) = 0        ! Darboux frames D_B, D_U, D_O
    integer :: body_frame(N_CONTACTS) = 0           ! P, L, T (the body each contact belongs to)
    integer :: u(N_CONTACTS) = 0, v(N_CONTACTS) = 0 ! scalar indices of the contacts' (u, v)
    integer :: joint(N_CONTACTS) = 0                ! element indices of the contacts' surface joints
    integer :: heading = 0, flexion = 0, tilt = 0   ! scalar indices of phi_B, phi_U, phi_O
    integer :: closure(6) = 0                       ! the six closure measurements
    integer :: contact(N_CONTACTS) = 0              ! mechanism contact indices
    integer :: friction(N_CONTACTS) = 0             ! law indices of the friction (0: none)
    integer :: drag(N_CONTACTS) = 0                 ! law indices of the water drag (0: none)
    integer :: heel_point = 0                       ! frame of the heel point (on the legs)
    !> the flight builds (build_rider's `open`, may_fly): the contacts that
    !> are open (pelvis, heels, back): an open limb's angle is a coordinate,
    !> its point held on its contact's normal only (x, y); the open pelvis
    !> is free (its lift and tilts coordinates)
    logical :: open(N_CONTACTS) = .false.
    !> the pelvis on the lift of the flight builds (free_pelvis): its lift h
    !> along the normal at its foot point (scalar index; 0 without)
    integer :: lift = 0
    integer :: point(N_CONTACTS) = 0                ! frames of the contact points (pelvis, heel, back)
    integer :: hold(2) = 0                          ! law indices of the hips' holds in flight (legs, trunk; 0: none)
    type(rider_body_t) :: body
  end type rider_layout_t

  real(wp), parameter :: sigma = 1, alpha_u = 1, alpha_v = 0
  real(wp), parameter :: ey(3) = [0.0_wp, 1.0_wp, 0.0_wp], ez(3) = [0.0_wp, 0.0_wp, 1.0_wp]

contains

  !> The rider's mechanism at its start q0 = [u, v0, heading0] (u the
  !> slide's parameter at the arc length u0: rider_start's start_parameter)
  !> with the dependent coordinates where heels and back meet the slide (refused, with
  !> which contact and by how much, if they cannot), its three one-sided
  !> contacts with the friction law of p (rider_friction; a law per weight
  !> takes the weight of the segment the contact belongs to: pelvis, legs,
  !> trunk, which add up to the rider's), and, given the computed water
  !> and p%drag, the water drag at each contact (on where the contact starts
  !> between the water's edges). Finalized, ready to run. The drag laws
  !> point at `water` (rider_water_drag): its actual argument outlives m.
  !>
  !> free_pelvis (default false; the flight builds, may_fly) adds the hips'
  !> holds of the posture in flight (rider_hip_hold, off) and puts the pelvis
  !> on a chain that can leave the slide: its foot point's surface joint
  !> (u_B, v_B), a prismatic along the normal there (the lift h), then the
  !> heading about the normal. With h at 0 (a constant while the pelvis is
  !> on) the pelvis frame is the plain model's, exactly.
  !>
  !> open (default none; docs/rider.md "Flight") opens contacts: an open
  !> heels' (back's) loop holds its point on the normal through the
  !> contact's foot point only (the x and y conditions, dependents u, v), so
  !> that its z measurement is the point's signed gap to the slide (positive
  !> on the rider's side), and the limb's angle phi_U (phi_O) is a
  !> coordinate; an open pelvis (free_pelvis needed) has its lift h as a
  !> coordinate and keeps its attitude to the slide below it (the flat
  !> seat's: docs/rider.md "Flight"). An open contact is two-sided: nothing presses there, its normal
  !> force is its foot frame's load, zero, and so is its friction. The
  !> coordinates are [u_B, v_B, phi_B], then phi_U, phi_O, h of the open
  !> ones. Scalars, frames, elements, contacts and laws are the
  !> same, at the same indices, in every build with one free_pelvis: a
  !> state maps one to one (rider_flight).
  subroutine build_rider(p, surface, m, layout, q0, status, water, open, free_pelvis)
    type(rider_params_t), intent(in) :: p
    class(surface_t), intent(in) :: surface
    type(mechanism_t), intent(out) :: m
    type(rider_layout_t), intent(out) :: layout
    real(wp), intent(out) :: q0(3)
    type(status_t), intent(inout) :: status
    type(water_field_t), intent(in), optional, target :: water
    logical, intent(in), optional :: open(N_CONTACTS), free_pelvis
    real(wp) :: g(2), u_start
    type(surface_point_t) :: pt
    type(darboux_frame_t) :: fr
    type(contact_reach_t) :: heels, back
    real(wp) :: axes(3, 3), hip(3)
    integer :: d_b, pelvis, hip_frame, legs, d_u, trunk, d_o, k, lifted
    logical :: chain
    integer, allocatable :: coordinates(:)
    type(spec_t) :: friction
    type(law_place_t) :: place   ! set by component: gfortran 12 leaks a constructor's name
    class(force_law_t), allocatable :: law
    real(wp) :: segment_weight(N_CONTACTS)   ! N

    q0 = [p%u0, p%v0, p%heading0]
    if (present(open)) layout%open = open
    chain = .false.
    if (present(free_pelvis)) chain = free_pelvis
    if (layout%open(CONTACT_PELVIS) .and. .not. chain) then
      call set_status(status, STATUS_INVALID_INPUT, 'an open pelvis needs the free chain (free_pelvis)')
      return
    end if
    call build_rider_body(p%body, layout%body, status)
    if (status%ok()) call start_parameter(surface, p%u0, u_start, status)
    if (.not. status%ok()) return
    q0(1) = u_start
    if (.not. surface%in_domain(u_start, p%v0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'the start u0 = '//format_short(p%u0)//' m, v0 = '// &
                      format_short(p%v0)//' lies off the slide')
      return
    end if
    call surface%evaluate(u_start, p%v0, 3, pt, status)
    if (status%ok()) call darboux_frame(pt, sigma, alpha_u, alpha_v, fr, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'rider start')
      return
    end if
    ! pelvis frame at the start: the Darboux frame turned by the heading
    axes(:, 1) = cos(p%heading0)*fr%r(:, 1) + sin(p%heading0)*fr%r(:, 2)
    axes(:, 3) = fr%r(:, 3)
    axes(:, 2) = -sin(p%heading0)*fr%r(:, 1) + cos(p%heading0)*fr%r(:, 2)
    hip = pt%r + matmul(axes, layout%body%hip)
    call reach_contact(surface, sigma, alpha_u, alpha_v, hip + matmul(axes, layout%body%heel), hip, -axes(:, 2), &
                       flexion_range, u_start, p%v0, heels, status)
    if (status%ok()) call reach_contact(surface, sigma, alpha_u, alpha_v, hip + matmul(axes, layout%body%back), hip, &
                                        axes(:, 2), tilt_range, u_start, p%v0, back, status)
    if (.not. status%ok()) return
    if (.not. heels%reached) then
      call set_status(status, STATUS_INVALID_INPUT, 'at the start the heels cannot reach the slide: '//heels%problem)
      return
    end if
    if (.not. back%reached) then
      call set_status(status, STATUS_INVALID_INPUT, 'at the start the back cannot reach the slide: '//back%problem)
      return
    end if

    ! pelvis: surface joint, heading, mass
    d_b = m%add_frame('pelvis_contact')
    layout%u(CONTACT_PELVIS) = m%add_scalar('u_pelvis', u_start)
    layout%v(CONTACT_PELVIS) = m%add_scalar('v_pelvis', p%v0)
    call m%add_element(new_surface_joint('pelvis_joint', 1, d_b, layout%u(CONTACT_PELVIS), &
                                         layout%v(CONTACT_PELVIS), surface, sigma, alpha_u, alpha_v))
    layout%joint(CONTACT_PELVIS) = m%n_elements
    if (chain) then
      ! foot point, lift along the normal, heading
      lifted = m%add_frame('pelvis_lifted')
      pelvis = m%add_frame('pelvis')
      layout%heading = m%add_scalar('heading', p%heading0)
      layout%lift = m%add_scalar('pelvis_lift', 0.0_wp)
      call m%add_element(new_prismatic('pelvis_lift', d_b, lifted, layout%lift, ez))
      call m%add_element(new_revolute('heading', lifted, pelvis, layout%heading, ez))
    else
      pelvis = m%add_frame('pelvis')
      layout%heading = m%add_scalar('heading', p%heading0)
      call m%add_element(new_revolute('heading', d_b, pelvis, layout%heading, ez))
    end if
    call m%add_element(new_mass_element('pelvis_mass', pelvis, layout%body%pelvis%mass, layout%body%pelvis%inertia, &
                                        layout%body%pelvis%com, p%gravity, status))
    hip_frame = m%add_frame('hip')
    call m%add_element(new_rigid_offset('pelvis_to_hip', pelvis, hip_frame, layout%body%hip))

    ! legs: flexion about -y, heel point, heel contact closed by three plane-point conditions
    call add_limb('legs', 'hip_flexion', -ey, layout%body%legs, 'heel', layout%body%heel, 'heels', CONTACT_HEELS, &
                  heels, legs, d_u, layout%flexion, layout%closure(1:3))
    ! trunk: tilt about +y, back point, back contact
    call add_limb('trunk', 'trunk_tilt', ey, layout%body%trunk, 'back', layout%body%back, 'back', CONTACT_BACK, &
                  back, trunk, d_o, layout%tilt, layout%closure(4:6))

    layout%contact_frame = [d_b, d_u, d_o]
    layout%body_frame = [pelvis, legs, trunk]
    layout%point(CONTACT_PELVIS) = pelvis
    coordinates = [layout%u(CONTACT_PELVIS), layout%v(CONTACT_PELVIS), layout%heading]
    if (layout%open(CONTACT_HEELS)) coordinates = [coordinates, layout%flexion]
    if (layout%open(CONTACT_BACK)) coordinates = [coordinates, layout%tilt]
    ! the open pelvis keeps its attitude to the slide below it (the flat
    ! seat's moments, whose normal force alone falls to zero at the lift-off)
    if (layout%open(CONTACT_PELVIS)) coordinates = [coordinates, layout%lift]
    call m%set_coordinates(coordinates)

    ! contacts (ground - body at the contact's Darboux frame), friction, drag
    friction = rider_friction(p)
    segment_weight = [layout%body%pelvis%mass, layout%body%legs%mass, layout%body%trunk%mass]*norm2(p%gravity)
    do k = 1, N_CONTACTS
      layout%contact(k) = m%add_contact(trim(contact_names(k)), 1, layout%body_frame(k), layout%contact_frame(k), &
                                        one_sided=p%one_sided .and. .not. layout%open(k))
      if (friction%kind /= 'none') then   ! a law of the core's registry (kinetostatics_force_law_factory)
        place%name = trim(contact_names(k))//'_friction'
        place%contact = layout%contact(k)
        place%weight = segment_weight(k)
        call force_law_from_spec(friction, place, law, status)
        if (.not. status%ok()) return
        call m%add_law(law)
        layout%friction(k) = m%n_laws
      end if
    end do
    if (present(water) .and. p%drag) then
      do k = 1, N_CONTACTS
        call in_water_roots(water, m%scalars(layout%u(k))%q, m%scalars(layout%v(k))%q, g)
        call m%add_law(new_water_drag(trim(contact_names(k))//'_drag', layout%contact(k), layout%u(k), &
                                      layout%v(k), p%drag_radius(k), p%water, water, all(g > 0)))
        layout%drag(k) = m%n_laws
      end do
    end if
    if (chain) then
      ! the posture's hold in flight (rider_hip_hold), off until a take-off
      call m%add_law(new_hip_hold('legs_hold', layout%flexion, hip_frame, legs, -ey, layout%body%legs))
      layout%hold(1) = m%n_laws
      call m%add_law(new_hip_hold('trunk_hold', layout%tilt, hip_frame, trunk, ey, layout%body%trunk))
      layout%hold(2) = m%n_laws
    end if
    call m%finalize(status)

  contains

    !> A limb on a revolute at the hip (`hinge` about `axis`, at the angle
    !> `reach` found), its mass `part`, its contact point at `offset` and the
    !> contact's surface joint at reach's (u, v), the point closed on the
    !> contact (close_point): the legs with the heels, the trunk with the back.
    !> The names of its frames, scalars and elements follow from limb, point
    !> and contact ('legs', 'heel', 'heels': 'phi_legs', 'heel_point', ...).
    subroutine add_limb(limb, hinge, axis, part, point, offset, contact, k, reach, frame, contact_frame, angle, &
                        closure)
      character(len=*), intent(in) :: limb, hinge, point, contact
      real(wp), intent(in) :: axis(3), offset(3)
      type(rigid_body_t), intent(in) :: part
      integer, intent(in) :: k
      type(contact_reach_t), intent(in) :: reach
      integer, intent(out) :: frame, contact_frame, angle, closure(3)
      integer :: point_frame
      frame = m%add_frame(limb)
      angle = m%add_scalar('phi_'//limb, reach%angle)
      call m%add_element(new_revolute(hinge, hip_frame, frame, angle, axis))
      call m%add_element(new_mass_element(limb//'_mass', frame, part%mass, part%inertia, part%com, p%gravity, status))
      point_frame = m%add_frame(point//'_point')
      if (k == CONTACT_HEELS) layout%heel_point = point_frame
      layout%point(k) = point_frame
      call m%add_element(new_rigid_offset(limb//'_to_'//point, frame, point_frame, offset))
      contact_frame = m%add_frame(point//'_contact')
      layout%u(k) = m%add_scalar('u_'//contact, reach%u)
      layout%v(k) = m%add_scalar('v_'//contact, reach%v)
      call m%add_element(new_surface_joint(point//'_joint', 1, contact_frame, layout%u(k), layout%v(k), surface, &
                                           sigma, alpha_u, alpha_v))
      layout%joint(k) = m%n_elements
      call close_point(contact, contact_frame, point_frame, [angle, layout%u(k), layout%v(k)], closure, &
                       layout%open(k))
    end subroutine add_limb

    !> Point `point` held at the origin of the Darboux frame `contact`:
    !> three plane-point measurements along its axes (4.27), one loop; open:
    !> on its z axis only (x and y, the dependents' last two: the contact's
    !> (u, v) at the point's foot point), z left free (the signed gap).
    subroutine close_point(name, contact, point, dependents, measurements, open)
      character(len=*), intent(in) :: name
      integer, intent(in) :: contact, point, dependents(3)
      integer, intent(out) :: measurements(3)
      logical, intent(in) :: open
      character(len=1), parameter :: axis_names(3) = ['x', 'y', 'z']
      integer :: i
      do i = 1, 3
        measurements(i) = m%add_scalar(name//'_'//axis_names(i))
      end do
      call m%add_element(new_point_coordinates(name, contact, point, measurements))
      if (open) then
        call m%add_loop(name, measurements(1:2), [0.0_wp, 0.0_wp], dependents(2:3), status)
      else
        call m%add_loop(name, measurements, [0.0_wp, 0.0_wp, 0.0_wp], dependents, status)
      end if
    end subroutine close_point
  end subroutine build_rider

  !> The friction law of p at the three contacts: p%friction, or, not set,
  !> Coulomb with the rider's mu_D (rider_default_mu).
  pure function rider_friction(p) result(spec)
    type(rider_params_t), intent(in) :: p
    type(spec_t) :: spec
    if (allocated(p%friction%kind)) then
      spec = p%friction
    else
      spec = law_spec('coulomb', 'mu', rider_default_mu)
    end if
  end function rider_friction

  !> The kind of p's friction law ('none' for none).
  pure function rider_friction_kind(p) result(kind)
    type(rider_params_t), intent(in) :: p
    character(len=:), allocatable :: kind
    type(spec_t) :: spec
    spec = rider_friction(p)
    kind = spec%kind
  end function rider_friction_kind

  !> The Coulomb mu of p's law, what the sweep varies and the identification
  !> fits: `coulomb` true for 'coulomb' and for 'none' (mu 0), false (mu 0)
  !> for any other law.
  pure subroutine rider_coulomb_mu(p, mu, coulomb)
    type(rider_params_t), intent(in) :: p
    real(wp), intent(out) :: mu
    logical, intent(out) :: coulomb
    type(spec_t) :: spec
    spec = rider_friction(p)
    mu = 0
    coulomb = spec%kind == 'coulomb' .or. spec%kind == 'none'
    if (spec%kind == 'coulomb') mu = spec%value('mu')
  end subroutine rider_coulomb_mu

  !> p with Coulomb friction mu at the three contacts (mu = 0: none), the
  !> other parameters of p's Coulomb law kept (the defaults after any other).
  pure subroutine set_rider_mu(p, mu)
    type(rider_params_t), intent(inout) :: p
    real(wp), intent(in) :: mu
    type(spec_t) :: spec
    spec = rider_friction(p)
    if (mu > 0) then
      if (spec%kind /= 'coulomb') spec = spec_t('coulomb')
      call spec%set('mu', [mu])
    else
      spec = spec_t('none')
    end if
    p%friction = spec
  end subroutine set_rider_mu

  !> q0' for the start speed along the body axis: r_u u' + r_v v' = speed x_P.
  subroutine rider_start_velocity(p, surface, qd0, status)
    type(rider_params_t), intent(in) :: p
    class(surface_t), intent(in) :: surface
    real(wp), intent(out) :: qd0(3)
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: pt
    type(darboux_frame_t) :: fr
    real(wp) :: w(3), e11, e12, e22, b1, b2, det, u_start
    qd0 = 0
    call start_parameter(surface, p%u0, u_start, status)
    if (status%ok()) call surface%evaluate(u_start, p%v0, 2, pt, status)
    if (status%ok()) call darboux_frame(pt, sigma, alpha_u, alpha_v, fr, status)
    if (.not. status%ok()) return
    w = p%speed0*(cos(p%heading0)*fr%r(:, 1) + sin(p%heading0)*fr%r(:, 2))
    e11 = dot_product(pt%ru, pt%ru)
    e12 = dot_product(pt%ru, pt%rv)
    e22 = dot_product(pt%rv, pt%rv)
    b1 = dot_product(pt%ru, w)
    b2 = dot_product(pt%rv, w)
    det = e11*e22 - e12**2
    qd0(1) = (e22*b1 - e12*b2)/det
    qd0(2) = (e11*b2 - e12*b1)/det
  end subroutine rider_start_velocity
end module rider_model
