!> Ready-made mechanisms built from the elements: simple and double pendulum,
!> four-bar linkage (a loop closed by two plane-point measurements) and the
!> sled (a bar on a surface, closed like the rider's legs in thesis (4.27)).
!> Scenarios, tests and benchmarks build their models here.
module kinetostatics_models
  use base_kinds, only: wp
  use base_constants, only: standard_gravity, dry_air_density
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_text, only: format_short
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use kinetostatics_joints, only: new_rigid_offset, new_revolute, new_prismatic
  use kinetostatics_surface_joint, only: new_surface_joint
  use kinetostatics_measurements, only: new_measurement, MEASURE_PLANE_POINT
  use kinetostatics_mass, only: new_mass_element
  use base_spec, only: spec_t
  use kinetostatics_force_law, only: force_law_t, law_place_t
  use kinetostatics_force_law_factory, only: force_law_from_spec
  use kinetostatics_force_laws, only: new_air_drag
  use kinetostatics_mechanism, only: mechanism_t
  implicit none (type, external)
  private
  public :: pendulum_params_t, build_pendulum, fourbar_params_t, build_fourbar, fourbar_assembly
  public :: sled_params_t, build_sled
  public :: pendulum_description_t, fourbar_description_t, sled_description_t
  public :: build_pendulum_model, build_fourbar_model, build_sled_model

  !> One or two links hanging from the ground, turning about the ground's y axis;
  !> link k carries a mass at distance length(k) along its -z axis.
  type :: pendulum_params_t
    integer :: links = 1
    real(wp) :: length(2) = 1        ! m
    real(wp) :: mass(2) = 1          ! kg
    real(wp) :: inertia(2) = 0       ! kg m^2 about the centre of mass (axis y and x)
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]   ! m/s^2
  end type pendulum_params_t

  !> Planar four-bar (revolutes about z): crank A-B (length a, angle q from x),
  !> coupler B-C (b), rocker D-C (c), ground A-D (d along x). Uniform rods.
  type :: fourbar_params_t
    real(wp) :: a = 0.2_wp, b = 0.6_wp, c = 0.5_wp, d = 0.7_wp       ! m
    real(wp) :: mass(3) = [0.5_wp, 1.0_wp, 0.8_wp]                   ! kg: crank, coupler, rocker
    real(wp) :: gravity(3) = [0.0_wp, -standard_gravity, 0.0_wp]           ! m/s^2
  end type fourbar_params_t

  !> A rigid bar (length L, centre of mass at L/2 on its axis unless
  !> centre_offset moves it) on a surface.
  type :: sled_params_t
    real(wp) :: length = 0.5_wp                 ! m
    real(wp) :: mass = 10                       ! kg
    !> m, bar frame: the centre of mass from the bar's middle [L/2, 0, 0]
    !> (a body above its runners: z > 0 on the side of the normal; the
    !> vehicles of rider_vehicle)
    real(wp) :: centre_offset(3) = 0
    real(wp) :: inertia(3, 3) = reshape([0.02_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.25_wp, 0.0_wp, &
                                         0.0_wp, 0.0_wp, 0.25_wp], [3, 3])   ! kg m^2, bar frame
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]
    !> The friction laws at both contacts, each a kind of the force-law
    !> registry with its parameters (kinetostatics_force_law_factory); none:
    !> frictionless
    type(spec_t), allocatable :: friction(:)
    !> Darboux frame parameters (3.38), (3.41); sigma must orient the normal
    !> z_D towards the side of the surface the bar is on (N > 0 while pressed)
    real(wp) :: sigma = 1, alpha_u = 1, alpha_v = 0
    !> Friction on the Darboux frames (the thesis's K_D of (4.28)) instead of on
    !> the bar at the contact points: the same generalized forces while the
    !> loops are closed (docs/multibody.md), kept to show that.
    logical :: loads_on_darboux_frames = .false.
    !> The front contact's normal force from the cut force of the closure
    !> measurement front_z (the rider's heels and back, METHOD-PART2 B.3)
    !> instead of the force on the front Darboux frame; the two are equal.
    logical :: front_normal_from_cut_force = .false.
    !> The air's drag on the bar at its centre of mass (air_drag_t, the law
    !> 'bar.air_drag'): C_d A (0: none), the air's density and velocity
    real(wp) :: drag_area = 0                   ! m^2
    real(wp) :: air_density = dry_air_density   ! kg/m^3
    real(wp) :: wind(3) = 0                     ! m/s, world
  end type sled_params_t

  !> A pendulum run as inputs say it (&pendulum): the model and its start.
  type :: pendulum_description_t
    type(pendulum_params_t) :: params
    real(wp) :: theta0(2) = [0.5_wp, 0.0_wp]    ! rad
    real(wp) :: dtheta0(2) = 0                  ! rad/s
  end type pendulum_description_t

  !> A four-bar run (&fourbar): the linkage, the crank's start and the branch.
  type :: fourbar_description_t
    type(fourbar_params_t) :: params
    real(wp) :: crank0 = 0                      ! rad
    real(wp) :: dcrank0 = 10                    ! rad/s
    integer :: branch = 1                       ! +1: C to the left of B->D, -1: right
  end type fourbar_description_t

  !> A sled run (&sled): the bar, its friction laws and its start; the
  !> surface is given beside it.
  type :: sled_description_t
    type(sled_params_t) :: params
    real(wp) :: q0(3) = 0                       ! u0, v0 (surface parameters), phi0 (rad)
    real(wp) :: qd0(3) = 0                      ! their rates
  end type sled_description_t

contains

  !> The pendulum of `d` and its start: q0, qd0 the links' angles and rates.
  subroutine build_pendulum_model(d, m, q0, qd0, status)
    type(pendulum_description_t), intent(in) :: d
    type(mechanism_t), intent(out) :: m
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(inout) :: status
    call build_pendulum(d%params, m, status)
    if (.not. status%ok()) return
    q0 = d%theta0(:d%params%links)
    qd0 = d%dtheta0(:d%params%links)
  end subroutine build_pendulum_model

  !> The four-bar of `d`, assembled on its branch at crank0 (the start of the
  !> closure; the closure itself decides), and its start: the crank's angle
  !> and rate.
  subroutine build_fourbar_model(d, m, q0, qd0, status)
    type(fourbar_description_t), intent(in) :: d
    type(mechanism_t), intent(out) :: m
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(inout) :: status
    real(wp) :: beta0(2)
    if (.not. status%ok()) return
    call fourbar_assembly(d%params, d%crank0, d%branch, beta0, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'loop ''coupler-rocker''')
      status%message = status%message//'; change a, b, c, d or crank0'
      return
    end if
    call build_fourbar(d%params, beta0, m, status)
    q0 = [d%crank0]
    qd0 = [d%dcrank0]
  end subroutine build_fourbar_model

  !> The sled of `d` on `surface` and its start: (u, v, phi) and their rates
  !> (finish = .false.: left open for more laws; lift, open, solve_yaw,
  !> free_roll: the flight builds; as build_sled).
  subroutine build_sled_model(d, surface, m, q0, qd0, status, finish, lift, open, solve_yaw, free_roll)
    type(sled_description_t), intent(in) :: d
    class(surface_t), intent(in) :: surface
    type(mechanism_t), intent(out) :: m
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: finish, lift, open(2), solve_yaw, free_roll
    if (.not. status%ok()) return
    if (.not. surface%in_domain(d%q0(1), d%q0(2))) then
      call set_status(status, STATUS_INVALID_INPUT, 'sled: the start (u0, v0) = ('//format_short(d%q0(1))//', '// &
                      format_short(d%q0(2))//') must lie in the parameter domain of the '//surface%describe())
      return
    end if
    call build_sled(d%params, surface, d%q0, m, status, finish, lift, open, solve_yaw, free_roll)
    q0 = d%q0
    qd0 = d%qd0
  end subroutine build_sled_model

  !> q = [theta_1(, theta_2)] (rad): absolute angle of link 1, relative angle of link 2.
  subroutine build_pendulum(p, m, status)
    type(pendulum_params_t), intent(in) :: p
    type(mechanism_t), intent(out) :: m
    type(status_t), intent(inout) :: status
    integer :: f1, f2, f3, t1, t2, k
    real(wp) :: inertia(3, 3)
    character(len=1) :: c
    if (p%links < 1 .or. p%links > 2) then
      call set_status(status, STATUS_INVALID_INPUT, 'pendulum: links must be 1 or 2')
      return
    end if
    f1 = m%add_frame('link1')
    t1 = m%add_scalar('theta1')
    call m%add_element(new_revolute('hinge1', 1, f1, t1, [0.0_wp, 1.0_wp, 0.0_wp]))
    do k = 1, p%links
      inertia = 0
      inertia(1, 1) = p%inertia(k)
      inertia(2, 2) = p%inertia(k)
      write (c, '(i1)') k
      if (k == 1) then
        call m%add_element(new_mass_element('bob1', f1, p%mass(1), inertia, [0.0_wp, 0.0_wp, -p%length(1)], &
                                            p%gravity, status))
      else
        f2 = m%add_frame('elbow')
        call m%add_element(new_rigid_offset('link1_rod', f1, f2, [0.0_wp, 0.0_wp, -p%length(1)]))
        f3 = m%add_frame('link2')
        t2 = m%add_scalar('theta2')
        call m%add_element(new_revolute('hinge2', f2, f3, t2, [0.0_wp, 1.0_wp, 0.0_wp]))
        call m%add_element(new_mass_element('bob2', f3, p%mass(2), inertia, [0.0_wp, 0.0_wp, -p%length(2)], &
                                            p%gravity, status))
      end if
    end do
    if (p%links == 1) then
      call m%set_coordinates([t1])
    else
      call m%set_coordinates([t1, t2])
    end if
    call m%finalize(status)
  end subroutine build_pendulum

  !> The dependent angles (coupler relative to crank, rocker absolute) for the
  !> crank angle q by intersecting two circles; branch +1 or -1 (C above or
  !> below the line B-D). Fails if the loop cannot be assembled.
  subroutine fourbar_assembly(p, q, branch, beta, status)
    type(fourbar_params_t), intent(in) :: p
    real(wp), intent(in) :: q
    integer, intent(in) :: branch
    real(wp), intent(out) :: beta(2)
    type(status_t), intent(inout) :: status
    real(wp) :: b(2), dd(2), e, x, y2, cpt(2), u(2)
    beta = 0
    b = p%a*[cos(q), sin(q)]
    dd = [p%d, 0.0_wp] - b
    e = norm2(dd)
    if (e > p%b + p%c .or. e < abs(p%b - p%c) .or. e == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'four-bar: the loop cannot be assembled at this crank '// &
                      'angle (|B - D| outside [|b - c|, b + c])')
      return
    end if
    x = (p%b**2 - p%c**2 + e**2)/(2*e)
    y2 = max(p%b**2 - x**2, 0.0_wp)
    u = dd/e
    cpt = b + x*u + branch*sqrt(y2)*[-u(2), u(1)]
    beta(1) = atan2(cpt(2) - b(2), cpt(1) - b(1)) - q
    beta(2) = atan2(cpt(2), cpt(1) - p%d)
  end subroutine fourbar_assembly

  !> q = [crank angle]; beta = [coupler angle relative to the crank, rocker angle]
  !> start from beta0; loop 'coupler-rocker' closes C (coupler end) on the two
  !> planes x = 0 and y = 0 of the rocker's end frame.
  subroutine build_fourbar(p, beta0, m, status)
    type(fourbar_params_t), intent(in) :: p
    real(wp), intent(in) :: beta0(2)
    type(mechanism_t), intent(out) :: m
    type(status_t), intent(inout) :: status
    integer :: crank, b_end, coupler, c_coupler, d_pivot, rocker, c_rocker, q, b1, b2, g1, g2
    real(wp), parameter :: z(3) = [0.0_wp, 0.0_wp, 1.0_wp]
    crank = m%add_frame('crank')
    q = m%add_scalar('crank_angle')
    call m%add_element(new_revolute('A', 1, crank, q, z))
    call m%add_element(new_mass_element('crank_mass', crank, p%mass(1), rod(p%mass(1), p%a), &
                                        [p%a/2, 0.0_wp, 0.0_wp], p%gravity, status))
    b_end = m%add_frame('B')
    call m%add_element(new_rigid_offset('crank_rod', crank, b_end, [p%a, 0.0_wp, 0.0_wp]))
    coupler = m%add_frame('coupler')
    b1 = m%add_scalar('coupler_angle', beta0(1))
    call m%add_element(new_revolute('B_joint', b_end, coupler, b1, z))
    call m%add_element(new_mass_element('coupler_mass', coupler, p%mass(2), rod(p%mass(2), p%b), &
                                        [p%b/2, 0.0_wp, 0.0_wp], p%gravity, status))
    c_coupler = m%add_frame('C_coupler')
    call m%add_element(new_rigid_offset('coupler_rod', coupler, c_coupler, [p%b, 0.0_wp, 0.0_wp]))
    d_pivot = m%add_frame('D')
    call m%add_element(new_rigid_offset('ground_link', 1, d_pivot, [p%d, 0.0_wp, 0.0_wp]))
    rocker = m%add_frame('rocker')
    b2 = m%add_scalar('rocker_angle', beta0(2))
    call m%add_element(new_revolute('D_joint', d_pivot, rocker, b2, z))
    call m%add_element(new_mass_element('rocker_mass', rocker, p%mass(3), rod(p%mass(3), p%c), &
                                        [p%c/2, 0.0_wp, 0.0_wp], p%gravity, status))
    c_rocker = m%add_frame('C_rocker')
    call m%add_element(new_rigid_offset('rocker_rod', rocker, c_rocker, [p%c, 0.0_wp, 0.0_wp]))
    g1 = m%add_scalar('closure_x')
    g2 = m%add_scalar('closure_y')
    call m%add_element(new_measurement('C_x', MEASURE_PLANE_POINT, c_rocker, c_coupler, g1, &
                                       axis_i=[1.0_wp, 0.0_wp, 0.0_wp]))
    call m%add_element(new_measurement('C_y', MEASURE_PLANE_POINT, c_rocker, c_coupler, g2, &
                                       axis_i=[0.0_wp, 1.0_wp, 0.0_wp]))
    call m%add_loop('coupler-rocker', [g1, g2], [0.0_wp, 0.0_wp], [b1, b2], status)
    call m%set_coordinates([q])
    call m%finalize(status)
  end subroutine build_fourbar

  !> Uniform thin rod along x: inertia diag(0, m l^2/12, m l^2/12) about its centre.
  pure function rod(mass, length) result(inertia)
    real(wp), intent(in) :: mass, length
    real(wp) :: inertia(3, 3)
    inertia = 0
    inertia(2, 2) = mass*length**2/12
    inertia(3, 3) = inertia(2, 2)
  end function rod

  !> q = [u, v, phi]: rear contact (surface joint 'rear') and the bar's heading
  !> about the normal; beta = [pitch, u2, v2]: the pitch revolute (about y)
  !> and the front contact (surface joint 'front'), closed by three plane-point
  !> measurements with the planes of the front Darboux frame (thesis (4.27)).
  !> beta starts from the projection of the front end onto the surface's
  !> tangent plane at (u0, v0), pitch 0. Contacts 'rear' and 'front' between
  !> the ground's surface and the bar (contact points: the two Darboux
  !> frames); each law of p%friction at both, 'rear_<kind>' and
  !> 'front_<kind>', in the order given. With
  !> finish = .false. the mechanism is left open for more laws or contacts
  !> (then call m%finalize).
  !>
  !> The flight builds (&sled may_fly, rider_vehicle_flight): `lift` puts
  !> the bar's rear end on a prismatic along the rear Darboux frame's normal
  !> (scalar 'rear_lift', 0 while the rear is on: the frames are the plain
  !> model's); `open` = [rear, front] opens contacts: an open rear has its
  !> lift as a coordinate (the bar keeps its roll to the slide below its
  !> rear end, as the rider's open pelvis), an open front is held on the
  !> normal through its foot point only (front_x, front_y; dependents u2,
  !> v2), so that front_z is its signed gap and the pitch a coordinate. An
  !> open contact is two-sided (its normal force its foot frame's load,
  !> zero, and so its friction). The coordinates are [u, v, phi], then pitch
  !> (front open) and rear_lift (rear open); scalars, frames, elements,
  !> contacts and laws are the same, at the same indices, in every build
  !> with `lift` (whose closed front pairs front_z with the pitch, front_x
  !> and front_y with u2 and v2, as the open front does). `solve_yaw` (with
  !> `lift` and the front closed): the front's closure solves front_z for
  !> the heading phi instead of the pitch, which becomes a coordinate
  !> ([u, v, pitch], then rear_lift): where the front's normal lies across
  !> the rear's, the pitch no longer moves the front off the slide but the
  !> heading does (rider_vehicle_flight picks the one by the normals).
  !> Every build with `lift` has the bar on a roll revolute about its own x
  !> after the pitch (scalar 'roll', frame 'pitched' between), held at its
  !> value (0 from the start); with a contact open and `free_roll` it is
  !> the last coordinate (both open: [u, v, phi, pitch, rear_lift, roll], a
  !> free rigid body; one open: five, a rigid body on one point contact;
  !> the roll's axis passes through both contact points, so neither
  !> contact's gap nor closure depends on it).
  subroutine build_sled(p, surface, q0, m, status, finish, lift, open, solve_yaw, free_roll)
    type(sled_params_t), intent(in) :: p
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: q0(3)
    type(mechanism_t), intent(out) :: m
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: finish, lift, open(2), solve_yaw, free_roll
    integer :: d1, heading, bar, front, d2, su, sv, sphi, spitch, su2, sv2, gx, gy, gz, rear_contact, &
               front_contact, front_body, lifted, slift, pitched, sroll
    logical :: chain, opened(2), yaw
    integer, allocatable :: coordinates(:)
    type(surface_point_t) :: pt
    type(darboux_frame_t) :: fr
    real(wp) :: dvec(3), e11, e12, e22, b1, b2, det, du, dv
    integer :: k

    call surface%evaluate(q0(1), q0(2), 3, pt, status)
    if (status%ok()) call darboux_frame(pt, p%sigma, p%alpha_u, p%alpha_v, fr, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'sled start')
      return
    end if
    dvec = p%length*(cos(q0(3))*fr%r(:, 1) + sin(q0(3))*fr%r(:, 2))
    e11 = dot_product(pt%ru, pt%ru); e12 = dot_product(pt%ru, pt%rv); e22 = dot_product(pt%rv, pt%rv)
    b1 = dot_product(pt%ru, dvec); b2 = dot_product(pt%rv, dvec)
    det = e11*e22 - e12**2
    du = (e22*b1 - e12*b2)/det
    dv = (e11*b2 - e12*b1)/det

    chain = .false.
    if (present(lift)) chain = lift
    opened = .false.
    if (present(open)) opened = open
    if (opened(1) .and. .not. chain) then
      call set_status(status, STATUS_INVALID_INPUT, 'sled: an open rear contact needs its lift (lift = .true.)')
      return
    end if
    yaw = .false.
    if (present(solve_yaw)) yaw = solve_yaw
    if (yaw .and. (opened(2) .or. .not. chain)) then
      call set_status(status, STATUS_INVALID_INPUT, 'sled: the heading is solved by a closed front with its '// &
                      'lift (lift = .true., the front not open)')
      return
    end if
    d1 = m%add_frame('rear_contact')
    su = m%add_scalar('u', q0(1))
    sv = m%add_scalar('v', q0(2))
    call m%add_element(new_surface_joint('rear', 1, d1, su, sv, surface, p%sigma, p%alpha_u, p%alpha_v))
    heading = m%add_frame('heading')
    sphi = m%add_scalar('phi', q0(3))
    slift = 0
    if (chain) then
      ! the rear end on the normal through its foot point, lifted by rear_lift
      lifted = m%add_frame('rear_lifted')
      slift = m%add_scalar('rear_lift', 0.0_wp)
      call m%add_element(new_prismatic('rear_lift', d1, lifted, slift, [0.0_wp, 0.0_wp, 1.0_wp]))
      call m%add_element(new_revolute('yaw', lifted, heading, sphi, [0.0_wp, 0.0_wp, 1.0_wp]))
    else
      call m%add_element(new_revolute('yaw', d1, heading, sphi, [0.0_wp, 0.0_wp, 1.0_wp]))
    end if
    spitch = m%add_scalar('pitch', 0.0_wp)
    sroll = 0
    if (chain) then
      pitched = m%add_frame('pitched')
      call m%add_element(new_revolute('pitch', heading, pitched, spitch, [0.0_wp, 1.0_wp, 0.0_wp]))
      bar = m%add_frame('bar')
      sroll = m%add_scalar('roll', 0.0_wp)
      call m%add_element(new_revolute('roll', pitched, bar, sroll, [1.0_wp, 0.0_wp, 0.0_wp]))
    else
      bar = m%add_frame('bar')
      call m%add_element(new_revolute('pitch', heading, bar, spitch, [0.0_wp, 1.0_wp, 0.0_wp]))
    end if
    call m%add_element(new_mass_element('bar_mass', bar, p%mass, p%inertia, [p%length/2, 0.0_wp, 0.0_wp] + &
                                        p%centre_offset, p%gravity, status))
    front = m%add_frame('bar_front')
    call m%add_element(new_rigid_offset('bar_rod', bar, front, [p%length, 0.0_wp, 0.0_wp]))
    d2 = m%add_frame('front_contact')
    su2 = m%add_scalar('u2', q0(1) + du)
    sv2 = m%add_scalar('v2', q0(2) + dv)
    call m%add_element(new_surface_joint('front', 1, d2, su2, sv2, surface, p%sigma, p%alpha_u, p%alpha_v))
    gx = m%add_scalar('front_x')
    gy = m%add_scalar('front_y')
    gz = m%add_scalar('front_z')
    call m%add_element(new_measurement('front_x', MEASURE_PLANE_POINT, d2, front, gx, axis_i=[1.0_wp, 0.0_wp, 0.0_wp]))
    call m%add_element(new_measurement('front_y', MEASURE_PLANE_POINT, d2, front, gy, axis_i=[0.0_wp, 1.0_wp, 0.0_wp]))
    call m%add_element(new_measurement('front_z', MEASURE_PLANE_POINT, d2, front, gz, axis_i=[0.0_wp, 0.0_wp, 1.0_wp]))
    if (opened(2)) then
      call m%add_loop('front contact', [gx, gy], [0.0_wp, 0.0_wp], [su2, sv2], status)
    else if (yaw) then
      call m%add_loop('front contact', [gz, gx, gy], [0.0_wp, 0.0_wp, 0.0_wp], [sphi, su2, sv2], status)
    else if (chain) then
      ! each condition with the same dependent as in the open loop (the
      ! records of the builds are joined by the dependents' names)
      call m%add_loop('front contact', [gz, gx, gy], [0.0_wp, 0.0_wp, 0.0_wp], [spitch, su2, sv2], status)
    else
      call m%add_loop('front contact', [gx, gy, gz], [0.0_wp, 0.0_wp, 0.0_wp], [spitch, su2, sv2], status)
    end if
    ! contacts of the bar with the ground's surface: sigma orients the Darboux
    ! z axes towards the side the bar is on, so N > 0 while it presses
    if (p%loads_on_darboux_frames) then
      rear_contact = m%add_contact('rear', 1, d1, d1)
    else if (chain) then
      rear_contact = m%add_contact('rear', 1, bar, d1, one_sided=.not. opened(1))
    else
      rear_contact = m%add_contact('rear', 1, bar, d1)
    end if
    front_body = bar
    if (p%loads_on_darboux_frames) front_body = d2
    if (p%front_normal_from_cut_force) then
      front_contact = m%add_contact('front', 1, front_body, d2, normal_measurement=gz)
    else if (chain) then
      front_contact = m%add_contact('front', 1, front_body, d2, one_sided=.not. opened(2))
    else
      front_contact = m%add_contact('front', 1, front_body, d2)
    end if
    ! the friction laws from their specs (kinetostatics_force_law_factory)
    if (allocated(p%friction)) then
      do k = 1, size(p%friction)
        call add_at_both(p%friction(k))
      end do
    end if
    if (status%ok() .and. p%drag_area /= 0) call m%add_law(new_air_drag('bar.air_drag', bar, &
      [p%length/2, 0.0_wp, 0.0_wp] + p%centre_offset, p%drag_area, p%air_density, p%wind, status))
    if (.not. status%ok()) return
    coordinates = [su, sv, sphi]
    if (yaw) coordinates = [su, sv, spitch]
    if (opened(2)) coordinates = [coordinates, spitch]
    if (opened(1)) coordinates = [coordinates, slift]
    if (present(free_roll) .and. any(opened) .and. chain) then
      if (free_roll) coordinates = [coordinates, sroll]
    end if
    call m%set_coordinates(coordinates)
    if (present(finish)) then
      if (.not. finish) return
    end if
    call m%finalize(status)

  contains

    !> The law `law` at the rear and the front contact ('rear_<kind>',
    !> 'front_<kind>'). Each contact carries half the sled's weight (a law
    !> per weight, viscous_weight: the two together give mu M g w_t, as one
    !> body of weight M g would)
    subroutine add_at_both(law)
      type(spec_t), intent(in) :: law
      class(force_law_t), allocatable :: built
      type(law_place_t) :: place   ! set by component: gfortran 12 leaks a constructor's name
      real(wp) :: half_weight
      half_weight = p%mass*norm2(p%gravity)/2
      place%name = 'rear_'//law%kind
      place%contact = rear_contact
      place%weight = half_weight
      call force_law_from_spec(law, place, built, status)
      if (status%ok()) call m%add_law(built)
      place%name = 'front_'//law%kind
      place%contact = front_contact
      place%weight = half_weight
      call force_law_from_spec(law, place, built, status)
      if (status%ok()) call m%add_law(built)
    end subroutine add_at_both
  end subroutine build_sled
end module kinetostatics_models
