!> A point mass sliding on a surface under gravity, in surface coordinates.
!>
!> State y = [u, v, u', v', W] with W the work done on the mass by friction (J,
!> negative), integrated alongside so that energy + |W| can be checked; with
!> the air's drag (drag_area > 0) one more, W_d, the drag's work. With
!> w = r_u u' + r_v v' the velocity and h = r_uu u'^2 + 2 r_uv u'v' + r_vv v'^2,
!> Newton's law m (r_u u'' + r_v v'' + h) = m g + N n + F_friction + F_drag
!> projected on r_u and r_v gives u'', v''; projected on the normal n it gives
!> the normal force N = m n.(h - g) - n.F_drag (as thesis eq. 4.12 does for
!> the water). Friction is tangential, so N does not depend on it and Coulomb
!> friction stays explicit. The drag is the contact scenario's law
!> (kinetostatics_force_laws air_drag_force): F_drag = -1/2 rho C_d A |w_r| w_r,
!> w_r = w - wind the velocity relative to the air. The friction
!> is any friction law of the core (kinetostatics_force_law friction_law_t,
!> built by kinetostatics_force_law_factory): its slip_force at the slip w and
!> the normal force N. A law with a regularization_speed that the description
!> leaves unset gets the point mass's own, 1e-9 m/s (point_mass_regularization_speed).
!>
!> The model runs through the integration driver (numerics_event_driver): it
!> records its own series (point_mass_series_t) and decides at the edges of
!> the surface's domain: an edge in u is the end of the ride (EVENT_STOP,
!> `outcome`), an edge in v the surface's side edge (an open section's wall
!> top: EVENT_STOP, 'over the side edge'), or a failure (STATUS_DOMAIN) where
!> the parametrisation is singular there (a pole). The events sit
!> domain_edge_margin inside the edges (kinetostatics_surface_joint).
module kinetostatics_point_mass
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_text, only: format_short
  use base_vector, only: cross
  use base_status, only: status_t, set_status, STATUS_DOMAIN, STATUS_INVALID_INPUT
  use base_series, only: growable_series_t, resize
  use numerics_event_driver, only: event_system_t, EVENT_IGNORE, EVENT_STOP
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use kinetostatics_surface_joint, only: domain_edge_margin
  use base_spec, only: spec_t
  use kinetostatics_force_law, only: force_law_t, friction_law_t, law_place_t, force_law_kind_t
  use kinetostatics_force_law_factory, only: force_law_from_spec, force_law_kinds, force_law_kind_index
  use kinetostatics_force_laws, only: air_drag_force
  use base_constants, only: dry_air_density
  implicit none (type, external)
  private
  public :: point_mass_t, point_mass_state_t, point_mass_series_t, point_mass_description_t, build_point_mass_model

  !> The regularization_speed of the point mass's friction law (m/s) where
  !> its description gives none, in place of the law's declared default: the
  !> contact's 1e-6 m/s would blur the point mass's slow slides (the shipped
  !> inputs were computed with 1e-9).
  real(wp), parameter :: point_mass_regularization_speed = 1e-9_wp

  !> Time series of a run: one entry per record (start, outputs, events).
  !> The records of a run; grown as it goes (base_series).
  !> Numbers of one record of point_mass_series_t (its arrays), for the memory bound
  integer, parameter :: values_per_record = 35

  type, extends(growable_series_t) :: point_mass_series_t
    real(wp), allocatable :: time(:), u(:), v(:), du(:), dv(:), speed(:), normal_force(:), &
      kinetic(:), potential(:), friction_work(:), drag_work(:)
    real(wp), allocatable :: position(:, :), velocity(:, :), acceleration(:, :), friction_force(:, :), &
      drag_force(:, :)
    real(wp), allocatable :: frame(:, :, :)
  end type point_mass_series_t

  type, extends(event_system_t) :: point_mass_t
    class(surface_t), allocatable :: surface
    real(wp) :: mass = 1                 ! kg
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]   ! m/s^2
    class(friction_law_t), allocatable :: friction   ! none: frictionless
    real(wp) :: drag_area = 0                  ! m^2, C_d A of the air's drag (0: none)
    real(wp) :: air_density = dry_air_density  ! kg/m^3
    real(wp) :: wind(3) = 0                    ! m/s, the air's velocity (world)
    real(wp) :: sigma = 1, alpha_u = 1, alpha_v = 0   ! Darboux frame parameters (3.38, 3.41)
    type(point_mass_series_t) :: series
    character(len=:), allocatable :: outcome   ! why the run ended, set by the stopping event
  contains
    procedure :: rhs => point_mass_rhs
    procedure :: root_count => point_mass_root_count
    procedure :: roots => point_mass_roots
    procedure :: state => point_mass_state
    procedure :: start_series => point_mass_start_series
    procedure :: record => point_mass_record
    procedure :: handle_event => point_mass_handle_event
  end type point_mass_t

  !> What a point-mass run is, as inputs say it (&point_mass): the mass,
  !> gravity, the friction law's spec, the frame's parameters and the start;
  !> the surface is given beside it. build_point_mass_model makes the model.
  type :: point_mass_description_t
    real(wp) :: mass = 1                           ! kg
    real(wp) :: u0 = 0, v0 = 0                     ! surface coordinates at t = 0
    real(wp) :: du0 = 0, dv0 = 0                   ! their rates at t = 0 (1/s)
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]   ! m/s^2
    type(spec_t) :: friction                       ! a force law kind and its parameters (no kind: none)
    real(wp) :: drag_area = 0                      ! m^2, C_d A of the air's drag (0: none)
    real(wp) :: air_density = dry_air_density      ! kg/m^3
    real(wp) :: wind(3) = 0                        ! m/s, the air's velocity (world)
    real(wp) :: sigma = 1, alpha_u = 1, alpha_v = 0
  end type point_mass_description_t

  !> Everything a user wants to see at one instant.
  type :: point_mass_state_t
    real(wp) :: position(3), velocity(3), acceleration(3)   ! m, m/s, m/s^2
    real(wp) :: speed                                       ! m/s
    real(wp) :: normal_force                                ! N, along the frame's z
    real(wp) :: friction_force(3)                           ! N
    real(wp) :: drag_force(3)                               ! N, the air's
    real(wp) :: kinetic_energy, potential_energy            ! J (potential -m g.r)
    real(wp) :: frame(3, 3)                                 ! Darboux frame, columns x, y, z
  end type point_mass_state_t

contains

  !> The model of `d` on `surface` (copied into it) and its start y0. The
  !> friction is built from its spec (kinetostatics_force_law_factory) and
  !> must be a friction law (of the slip and the normal force); the start
  !> must lie in the surface's domain. y0 = [u0, v0, du0, dv0, 0] and with
  !> the air's drag one more 0 (its work).
  subroutine build_point_mass_model(d, surface, model, y0, status)
    type(point_mass_description_t), intent(in) :: d
    class(surface_t), intent(in) :: surface
    type(point_mass_t), intent(out) :: model
    real(wp), allocatable, intent(out) :: y0(:)
    type(status_t), intent(inout) :: status
    class(force_law_t), allocatable :: law
    type(spec_t) :: friction
    type(law_place_t) :: place
    y0 = [d%u0, d%v0, d%du0, d%dv0, 0.0_wp]
    if (d%drag_area > 0) y0 = [y0, 0.0_wp]
    if (.not. status%ok()) return
    allocate (model%surface, source=surface)
    model%mass = d%mass
    model%gravity = d%gravity
    model%drag_area = d%drag_area
    model%air_density = d%air_density
    model%wind = d%wind
    model%sigma = d%sigma
    model%alpha_u = d%alpha_u
    model%alpha_v = d%alpha_v
    if (.not. surface%in_domain(d%u0, d%v0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'point mass: the start (u0, v0) = ('//format_short(d%u0)// &
                      ', '//format_short(d%v0)//') must lie in the parameter domain of the '//surface%describe())
      return
    end if
    if (.not. allocated(d%friction%kind)) return
    ! named and set by component: gfortran 12 leaks the allocatable components of a
    ! function result or structure constructor passed as an argument
    friction = point_mass_friction(d%friction)
    place%name = 'friction'
    place%contact = 0
    place%weight = d%mass*norm2(d%gravity)
    call force_law_from_spec(friction, place, law, status)
    if (.not. status%ok()) return
    select type (law)
    class is (friction_law_t)
      allocate (model%friction, source=law)
    class default
      call set_status(status, STATUS_INVALID_INPUT, 'point mass: friction '''//d%friction%kind//''' is not a '// &
                      'friction law: the point mass takes a friction law of the slip and the normal force (a '// &
                      'friction_law_t)')
    end select
  end subroutine build_point_mass_model

  !> `friction` with the point mass's regularization_speed where its law
  !> declares one and the spec leaves it unset (an unknown kind is left to
  !> force_law_from_spec to refuse).
  function point_mass_friction(friction) result(spec)
    type(spec_t), intent(in) :: friction
    type(spec_t) :: spec
    type(force_law_kind_t), allocatable :: laws(:)
    integer :: k, j
    spec = friction
    k = force_law_kind_index(friction%kind)
    if (k == 0 .or. friction%has('regularization_speed')) return
    laws = force_law_kinds()
    if (any([(laws(k)%parameters(j)%name == 'regularization_speed', j = 1, size(laws(k)%parameters))])) &
      call spec%set('regularization_speed', [point_mass_regularization_speed])
  end function point_mass_friction

  !> The accelerations and forces at one state; the one place the dynamics live.
  pure subroutine dynamics(self, y, p, normal, udd, vdd, normal_force, friction, drag, status)
    class(point_mass_t), intent(in) :: self
    real(wp), intent(in) :: y(:)
    type(surface_point_t), intent(out) :: p
    real(wp), intent(out) :: normal(3), udd, vdd, normal_force, friction(3), drag(3)
    type(status_t), intent(inout) :: status
    real(wp) :: w(3), h(3), rhs(3), e, f, g, det, bu, bv, n(3), n_norm
    type(darboux_frame_t) :: frame

    if (.not. self%surface%in_domain(y(1), y(2))) then
      call set_status(status, STATUS_DOMAIN, 'the mass left the surface''s parameter domain at (u, v) = (' &
                      //format_short(y(1))//', '//format_short(y(2))//')')
      return
    end if
    call self%surface%evaluate(y(1), y(2), 2, p, status)
    if (.not. status%ok()) return
    n = cross(p%ru, p%rv)
    n_norm = norm2(n)
    if (n_norm > 1e-12_wp*dot_product(p%rv, p%rv)) then
      normal = sign(1.0_wp, self%sigma)*n/n_norm    ! thesis (3.38)
    else
      ! r_u x r_v = 0: the frame's singular-point rule (3.39-3.40) gives the
      ! normal; its rates need third partials, so evaluate once more to order 3.
      call self%surface%evaluate(y(1), y(2), 3, p, status)
      if (.not. status%ok()) return
      call darboux_frame(p, self%sigma, self%alpha_u, self%alpha_v, frame, status)
      if (.not. status%ok()) return
      normal = frame%R(:, 3)
    end if

    w = p%ru*y(3) + p%rv*y(4)
    h = p%ruu*y(3)**2 + 2*p%ruv*y(3)*y(4) + p%rvv*y(4)**2
    drag = 0
    if (self%drag_area > 0) drag = air_drag_force(w, self%drag_area, self%air_density, self%wind)
    normal_force = self%mass*dot_product(normal, h - self%gravity)
    if (self%drag_area > 0) normal_force = normal_force - dot_product(normal, drag)

    if (allocated(self%friction)) then
      friction = self%friction%slip_force(w, normal_force)
    else
      friction = 0
    end if

    rhs = self%gravity + friction/self%mass - h
    if (self%drag_area > 0) rhs = rhs + drag/self%mass
    e = dot_product(p%ru, p%ru)
    f = dot_product(p%ru, p%rv)
    g = dot_product(p%rv, p%rv)
    bu = dot_product(p%ru, rhs)
    bv = dot_product(p%rv, rhs)
    det = e*g - f*f
    if (e <= 1e-24_wp*g) then
      ! Singular point r_u = 0 (the apex of a polar parametrization): u'' does not
      ! move the mass, so take u'' = 0 and v'' from the r_v component.
      udd = 0
      vdd = bv/g
    else
      udd = (g*bu - f*bv)/det
      vdd = (e*bv - f*bu)/det
    end if
  end subroutine dynamics

  subroutine point_mass_rhs(self, t, y, ydot, status)
    class(point_mass_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: p
    real(wp) :: normal(3), udd, vdd, normal_force, friction(3), drag(3)

    associate (unused => t)   ! autonomous: no explicit time dependence
    end associate
    call dynamics(self, y, p, normal, udd, vdd, normal_force, friction, drag, status)
    if (.not. status%ok()) then
      ydot = 0
      return
    end if
    ydot(1) = y(3)
    ydot(2) = y(4)
    ydot(3) = udd
    ydot(4) = vdd
    ydot(5) = dot_product(friction, p%ru*y(3) + p%rv*y(4))   ! friction power, W
    if (size(ydot) > 5) ydot(6) = dot_product(drag, p%ru*y(3) + p%rv*y(4))   ! the drag's power, W
  end subroutine point_mass_rhs

  !> Four root functions: the distances to the edges u_min, u_max, v_min, v_max
  !> of the parameter domain less domain_edge_margin (1 where a direction is
  !> periodic or unbounded), so a run stops where the mass reaches an edge.
  integer function point_mass_root_count(self) result(n)
    class(point_mass_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 4
  end function point_mass_root_count

  subroutine point_mass_roots(self, t, y, g)
    class(point_mass_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    real(wp) :: u_min, u_max, v_min, v_max
    associate (unused => t)
    end associate
    call self%surface%domain(u_min, u_max, v_min, v_max)
    g = 1
    if (.not. self%surface%periodic_u()) then
      if (u_min > -huge(u_min)) g(1) = y(1) - u_min - domain_edge_margin(u_min, u_max)
      if (u_max < huge(u_max)) g(2) = u_max - domain_edge_margin(u_min, u_max) - y(1)
    end if
    if (.not. self%surface%periodic_v()) then
      if (v_min > -huge(v_min)) g(3) = y(2) - v_min - domain_edge_margin(v_min, v_max)
      if (v_max < huge(v_max)) g(4) = v_max - domain_edge_margin(v_min, v_max) - y(2)
    end if
  end subroutine point_mass_roots

  !> An edge in u ends the ride (the end of a slide, or back at its start);
  !> an edge in v too (over the side edge), unless it is a pole: a failure.
  subroutine point_mass_handle_event(self, t, y, fired, action, status)
    class(point_mass_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: p
    real(wp) :: ratio
    action = EVENT_IGNORE
    if (any(fired(3:4) == -1)) then
      ! a pole (a singular parametrisation, as the mechanism's surface joints
      ! judge it: |r_u x r_v| below 1e-2 (|r_u|^2 + |r_v|^2)) is a failure;
      ! any other edge in v is the surface's side edge (an open section's
      ! wall top): the mass goes over it, a normal end
      call self%surface%evaluate(y(1), y(2), 1, p, status)
      if (.not. status%ok()) return
      ratio = norm2(cross(p%ru, p%rv))/max(dot_product(p%ru, p%ru) + dot_product(p%rv, p%rv), tiny(1.0_wp))
      if (ratio < 1e-2_wp) then
        call set_status(status, STATUS_DOMAIN, 'the mass reached the edge of the surface''s parameter domain '// &
                        'at a pole of its parametrisation, (u, v) = ('//format_short(y(1))//', '// &
                        format_short(y(2))//')')
        return
      end if
      action = EVENT_STOP
      self%outcome = 'over the side edge: the mass reached the edge v = '//format_short(y(2))// &
                     ' of the surface at u = '//format_short(y(1))//' (t = '//format_short(t)//' s)'
    else if (any(fired(1:2) == -1)) then
      action = EVENT_STOP
      self%outcome = 'reached the end of the surface at u = '//format_short(y(1))//' (t = '//format_short(t)//' s)'
    end if
  end subroutine point_mass_handle_event

  !> Empty series with room for `capacity` records (it grows when needed).
  subroutine point_mass_start_series(self, capacity)
    class(point_mass_t), intent(inout) :: self
    integer, intent(in) :: capacity
    self%series%n = 0
    call allocate_series(self%series, max(capacity, 2))
    self%outcome = ''
  end subroutine point_mass_start_series

  !> Room for n records in every array of the series, the recorded ones kept.
  subroutine allocate_series(s, n)
    type(point_mass_series_t), intent(inout) :: s
    integer, intent(in) :: n
    call resize(s%time, n); call resize(s%u, n); call resize(s%v, n); call resize(s%du, n)
    call resize(s%dv, n); call resize(s%speed, n); call resize(s%normal_force, n); call resize(s%kinetic, n)
    call resize(s%potential, n); call resize(s%friction_work, n); call resize(s%drag_work, n)
    call resize(s%position, 3, n); call resize(s%velocity, 3, n); call resize(s%acceleration, 3, n)
    call resize(s%friction_force, 3, n); call resize(s%drag_force, 3, n); call resize(s%frame, 3, 3, n)
    s%capacity = n
  end subroutine allocate_series

  !> Appends the state at (t, y) to the series (whatever the record kind).
  subroutine point_mass_record(self, t, y, kind, status)
    class(point_mass_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    type(point_mass_state_t) :: state
    integer :: i, grown
    associate (unused => kind)
    end associate
    call self%state(y, state, status)
    if (.not. status%ok()) return
    if (.not. allocated(self%series%time)) call self%start_series(100)
    call self%series%make_room(16, 8.0_wp*values_per_record, 'point_mass', t, grown, status)
    if (.not. status%ok()) return
    if (grown > 0) call allocate_series(self%series, grown)
    associate (s => self%series)
      s%n = s%n + 1
      i = s%n
      s%time(i) = t
      s%u(i) = y(1); s%v(i) = y(2); s%du(i) = y(3); s%dv(i) = y(4)
      s%friction_work(i) = y(5)
      s%drag_work(i) = 0
      if (size(y) > 5) s%drag_work(i) = y(6)
      s%position(:, i) = state%position
      s%velocity(:, i) = state%velocity
      s%acceleration(:, i) = state%acceleration
      s%speed(i) = state%speed
      s%normal_force(i) = state%normal_force
      s%friction_force(:, i) = state%friction_force
      s%drag_force(:, i) = state%drag_force
      s%kinetic(i) = state%kinetic_energy
      s%potential(i) = state%potential_energy
      s%frame(:, :, i) = state%frame
    end associate
  end subroutine point_mass_record

  subroutine point_mass_state(self, y, state, status)
    class(point_mass_t), intent(in) :: self
    real(wp), intent(in) :: y(:)
    type(point_mass_state_t), intent(out) :: state
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: p
    type(darboux_frame_t) :: frame
    real(wp) :: normal(3), udd, vdd

    call dynamics(self, y, p, normal, udd, vdd, state%normal_force, state%friction_force, state%drag_force, status)
    if (.not. status%ok()) return
    call self%surface%evaluate(y(1), y(2), 3, p, status)   ! order 3: singular points need it
    if (.not. status%ok()) return
    call darboux_frame(p, self%sigma, self%alpha_u, self%alpha_v, frame, status)
    state%frame = frame%R
    state%position = p%r
    state%velocity = p%ru*y(3) + p%rv*y(4)
    state%acceleration = p%ru*udd + p%rv*vdd + p%ruu*y(3)**2 + 2*p%ruv*y(3)*y(4) + p%rvv*y(4)**2
    state%speed = norm2(state%velocity)
    state%kinetic_energy = 0.5_wp*self%mass*dot_product(state%velocity, state%velocity)
    state%potential_energy = -self%mass*dot_product(self%gravity, p%r)
  end subroutine point_mass_state
end module kinetostatics_point_mass
