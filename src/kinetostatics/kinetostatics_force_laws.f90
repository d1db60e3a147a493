!> The force laws of the core (the seam is kinetostatics_force_law):
!>
!>   coulomb_friction_t        F = -mu |N| w_t/sqrt(|w_t|^2 + eps^2)   (thesis 4.28)
!>   viscous_friction_t        F = -c w_t (new_viscous_friction), or scaled by
!>                             the normal force F = -mu |N| w_t with mu in s/m
!>                             (new_normal_viscous_friction: the spinning egg's
!>                             law, METHOD-PART2 A.4.3)
!>   spring_damper_t           between a point of frame i and a point of frame j
!>   constant_load_t           a constant wrench at a frame (world or body axes)
!>   air_drag_t                the air's quadratic drag on a body, at its centre
!>                             of mass: F = -1/2 rho C_d A |w| w, w = v_S - wind
!>
!> The friction laws are friction_law_t (kinetostatics_force_law): a force
!> F(w_t, N) with w_t the tangential part of the material slip velocity, F on
!> body B and -F on body A. Coulomb and the N-scaled viscous law are scaled
!> laws: their load is |N| times a state-dependent vector, solved exactly
!> together with q''.
!>
!> The kinds inputs name (registered in kinetostatics_force_law_factory):
!>   coulomb          mu (1), regularization_speed (m/s)
!>   viscous          viscous_coefficient (N s/m): F = -c w_t
!>   viscous_weight   mu (s/m): F = -mu M g w_t, M g the weight of the body
!>                    the contact carries (the egg's law, METHOD-PART2 A.4.3)
!>   viscous_normal   mu (s/m): F = -mu |N| w_t
!> Coulomb friction near w = 0: eps = regularization_speed, exact to
!> (eps/|w|)^2/2 relative while sliding; a contact at rest feels a stiff
!> viscous damping mu |N|/eps instead of stiction (sticking is not modelled).
module kinetostatics_force_laws
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_vector, only: cross
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_spec, only: spec_t, declare
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_contact, only: contact_state_t
  use kinetostatics_force_law, only: force_law_t, friction_law_t, frame_load_t, force_law_kind_t, law_place_t, &
    force_at, set_interaction
  implicit none (type, external)
  private
  public :: coulomb_friction_t, viscous_friction_t, spring_damper_t, constant_load_t, air_drag_t, air_drag_force
  public :: new_coulomb_friction, new_normal_viscous_friction, new_viscous_friction, new_spring_damper, &
    new_constant_load, new_air_drag
  public :: coulomb_kind, viscous_kind, viscous_weight_kind, viscous_normal_kind

  type, extends(friction_law_t) :: coulomb_friction_t
    real(wp) :: mu = 0                          ! 1
    real(wp) :: regularization_speed = 1e-6_wp  ! m/s
  contains
    procedure :: slip_force => coulomb_slip_force
  end type coulomb_friction_t

  !> F = -coefficient w_t; scaled: times |N| (coefficient in s/m, else N s/m).
  type, extends(friction_law_t) :: viscous_friction_t
    real(wp) :: coefficient = 0
  contains
    procedure :: slip_force => viscous_slip_force
  end type viscous_friction_t

  !> Tension f = k (l - rest_length) + c l' along the line from the point on
  !> frame i to the point on frame j (l their distance): -f e on j's point,
  !> +f e on i's, e the unit vector from i's point to j's.
  type, extends(force_law_t) :: spring_damper_t
    integer :: frame_i = 0, frame_j = 0
    real(wp) :: point_i(3) = 0, point_j(3) = 0  ! m, in the frames' own axes
    real(wp) :: stiffness = 0                   ! N/m
    real(wp) :: rest_length = 0                 ! m
    real(wp) :: damping = 0                     ! N s/m
  contains
    procedure :: evaluate => spring_evaluate
  end type spring_damper_t

  !> A constant force and torque (about the frame's origin) at a frame, in
  !> world axes, or in the frame's own axes if body_fixed.
  type, extends(force_law_t) :: constant_load_t
    integer :: frame = 0
    real(wp) :: force_value(3) = 0, torque_value(3) = 0   ! N, N m
    logical :: body_fixed = .false.
  contains
    procedure :: evaluate => constant_evaluate
  end type constant_load_t

  !> The air's drag on a body, F = -1/2 rho C_d A |w| w at its centre of
  !> mass S, w = v_S - wind its velocity relative to the air (still air:
  !> wind = 0): a force along -w only (no lift, no turning moment about S:
  !> the rotational drag of a spinning body is not modelled). Its power
  !> F.v_S is the work the air does on the body; in still air -F.v_S =
  !> 1/2 rho C_d A |v_S|^3 >= 0 is dissipated.
  type, extends(force_law_t) :: air_drag_t
    integer :: frame = 0
    real(wp) :: centre(3) = 0       ! m, the centre of mass in the frame's own axes
    real(wp) :: drag_area = 0       ! m^2, C_d A
    real(wp) :: density = 0         ! kg/m^3
    real(wp) :: wind(3) = 0         ! m/s, the air's velocity (world)
  contains
    procedure :: evaluate => air_drag_evaluate
  end type air_drag_t

contains

  subroutine check_coefficient(law, what, value, unit, status)
    character(len=*), intent(in) :: law, what, unit
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    if (.not. (value >= 0 .and. value < huge(value))) call set_status(status, STATUS_INVALID_INPUT, &
      'force law '''//law//''': '//what//' = '//format_short(value)//' '//unit//'; it must be finite and >= 0')
  end subroutine check_coefficient

  !> Coulomb friction at contact `contact` (index from mechanism%add_contact).
  function new_coulomb_friction(name, contact, mu, regularization_speed, status) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: contact
    real(wp), intent(in) :: mu, regularization_speed
    type(status_t), intent(inout) :: status
    type(coulomb_friction_t) :: law
    call law%set_up_contact_law(name, contact, scaled=.true.)
    law%mu = mu
    law%regularization_speed = regularization_speed
    call check_coefficient(name, 'mu', mu, '', status)
    if (.not. (regularization_speed > 0 .and. regularization_speed < huge(1.0_wp))) &
      call set_status(status, STATUS_INVALID_INPUT, 'force law '''//name//''': regularization_speed = '// &
                      format_short(regularization_speed)//' m/s; it must be finite and > 0')
  end function new_coulomb_friction

  !> -mu |N| w/sqrt(|w|^2 + eps^2) (thesis 4.28)
  pure function coulomb_slip_force(self, slip, normal_force) result(force)
    class(coulomb_friction_t), intent(in) :: self
    real(wp), intent(in) :: slip(3), normal_force
    real(wp) :: force(3)
    force = -self%mu*abs(normal_force)*slip/sqrt(dot_product(slip, slip) + self%regularization_speed**2)
  end function coulomb_slip_force

  !> Viscous friction F = -c w_t (c in N s/m).
  function new_viscous_friction(name, contact, coefficient, status) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: contact
    real(wp), intent(in) :: coefficient
    type(status_t), intent(inout) :: status
    type(viscous_friction_t) :: law
    call law%set_up_contact_law(name, contact, scaled=.false.)
    law%coefficient = coefficient
    call check_coefficient(name, 'viscous coefficient', coefficient, 'N s/m', status)
  end function new_viscous_friction

  !> Viscous friction proportional to the normal force, F = -mu |N| w_t (mu in s/m).
  function new_normal_viscous_friction(name, contact, mu, status) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: contact
    real(wp), intent(in) :: mu
    type(status_t), intent(inout) :: status
    type(viscous_friction_t) :: law
    call law%set_up_contact_law(name, contact, scaled=.true.)
    law%coefficient = mu
    call check_coefficient(name, 'mu', mu, 's/m', status)
  end function new_normal_viscous_friction

  !> -c w, or -mu |N| w (scaled)
  pure function viscous_slip_force(self, slip, normal_force) result(force)
    class(viscous_friction_t), intent(in) :: self
    real(wp), intent(in) :: slip(3), normal_force
    real(wp) :: force(3)
    if (self%scaled) then
      force = -self%coefficient*abs(normal_force)*slip
    else
      force = -self%coefficient*slip
    end if
  end function viscous_slip_force

  ! ------------------------------------------------------ the kinds inputs name

  function coulomb_kind() result(kind)
    type(force_law_kind_t) :: kind
    kind%name = 'coulomb'
    kind%meaning = 'Coulomb friction -mu |N| w_t/|w_t|, regularized near w_t = 0'
    kind%parameters = [declare('mu', '1', 0.0_wp, 10.0_wp, 'friction coefficient', open_low=.true.), &
                       declare('regularization_speed', 'm/s', 0.0_wp, 1.0_wp, 'slip speed below which the '// &
                               'law turns viscous', default=[1e-6_wp], open_low=.true.)]
    kind%build => build_coulomb
  end function coulomb_kind

  subroutine build_coulomb(spec, place, law, status)
    type(spec_t), intent(in) :: spec
    type(law_place_t), intent(in) :: place
    class(force_law_t), allocatable, intent(out) :: law
    type(status_t), intent(inout) :: status
    allocate (law, source=new_coulomb_friction(place%name, place%contact, spec%value('mu'), &
                                               spec%value('regularization_speed'), status))
  end subroutine build_coulomb

  function viscous_kind() result(kind)
    type(force_law_kind_t) :: kind
    kind%name = 'viscous'
    kind%meaning = 'viscous friction -c w_t'
    kind%parameters = [declare('viscous_coefficient', 'N s/m', 0.0_wp, 1e6_wp, 'c')]
    kind%build => build_viscous
  end function viscous_kind

  subroutine build_viscous(spec, place, law, status)
    type(spec_t), intent(in) :: spec
    type(law_place_t), intent(in) :: place
    class(force_law_t), allocatable, intent(out) :: law
    type(status_t), intent(inout) :: status
    allocate (law, source=new_viscous_friction(place%name, place%contact, spec%value('viscous_coefficient'), &
                                               status))
  end subroutine build_viscous

  function viscous_weight_kind() result(kind)
    type(force_law_kind_t) :: kind
    kind%name = 'viscous_weight'
    kind%meaning = 'viscous friction -mu M g w_t, M g the weight of the body the contact carries'
    kind%parameters = [declare('mu', 's/m', 0.0_wp, 1e3_wp, 'coefficient per weight', open_low=.true.)]
    kind%build => build_viscous_weight
  end function viscous_weight_kind

  subroutine build_viscous_weight(spec, place, law, status)
    type(spec_t), intent(in) :: spec
    type(law_place_t), intent(in) :: place
    class(force_law_t), allocatable, intent(out) :: law
    type(status_t), intent(inout) :: status
    allocate (law, source=new_viscous_friction(place%name, place%contact, spec%value('mu')*place%weight, &
                                               status))
  end subroutine build_viscous_weight

  function viscous_normal_kind() result(kind)
    type(force_law_kind_t) :: kind
    kind%name = 'viscous_normal'
    kind%meaning = 'viscous friction -mu |N| w_t'
    kind%parameters = [declare('mu', 's/m', 0.0_wp, 1e3_wp, 'coefficient per normal force', open_low=.true.)]
    kind%build => build_viscous_normal
  end function viscous_normal_kind

  subroutine build_viscous_normal(spec, place, law, status)
    type(spec_t), intent(in) :: spec
    type(law_place_t), intent(in) :: place
    class(force_law_t), allocatable, intent(out) :: law
    type(status_t), intent(inout) :: status
    allocate (law, source=new_normal_viscous_friction(place%name, place%contact, spec%value('mu'), status))
  end subroutine build_viscous_normal

  !> A spring and damper between point_i on frame_i and point_j on frame_j
  !> (points in the frames' own axes).
  function new_spring_damper(name, frame_i, point_i, frame_j, point_j, stiffness, rest_length, damping, &
                             status) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_i, frame_j
    real(wp), intent(in) :: point_i(3), point_j(3), stiffness, rest_length, damping
    type(status_t), intent(inout) :: status
    type(spring_damper_t) :: law
    law%name = name
    law%frame_i = frame_i
    law%frame_j = frame_j
    law%point_i = point_i
    law%point_j = point_j
    law%stiffness = stiffness
    law%rest_length = rest_length
    law%damping = damping
    allocate (law%loads(2))
    call check_coefficient(name, 'stiffness', stiffness, 'N/m', status)
    call check_coefficient(name, 'rest length', rest_length, 'm', status)
    call check_coefficient(name, 'damping', damping, 'N s/m', status)
  end function new_spring_damper

  pure subroutine spring_evaluate(self, t, frames, scalars, contacts, status)
    class(spring_damper_t), intent(inout) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    type(status_t), intent(inout) :: status
    real(wp) :: arm_i(3), arm_j(3), d(3), dv(3), length, e(3), tension, f(3)
    associate (unused_t => t, unused_s => scalars, unused_c => contacts)
    end associate
    associate (fi => frames(self%frame_i), fj => frames(self%frame_j))
      arm_i = matmul(fi%rot, self%point_i)
      arm_j = matmul(fj%rot, self%point_j)
      d = fj%r + arm_j - fi%r - arm_i
      dv = fj%v + cross(fj%omega, arm_j) - fi%v - cross(fi%omega, arm_i)
      length = norm2(d)
      if (length <= 1e-12_wp*max(self%rest_length, 1.0_wp)) then
        if (self%rest_length > 0 .or. self%damping > 0) then
          call set_status(status, STATUS_DOMAIN, 'spring '''//self%name//''': its two points coincide '// &
                          '(no direction for the force)')
          self%loads = frame_load_t()
          return
        end if
        e = 0
      else
        e = d/length
      end if
      tension = self%stiffness*(length - self%rest_length) + self%damping*dot_product(e, dv)
      f = -tension*e
      call set_interaction(self%loads, self%frame_j, arm_j, self%frame_i, arm_i, f)
    end associate
  end subroutine spring_evaluate

  function new_constant_load(name, frame, force, torque, body_fixed) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame
    real(wp), intent(in) :: force(3), torque(3)
    logical, intent(in) :: body_fixed
    type(constant_load_t) :: law
    law%name = name
    law%frame = frame
    law%force_value = force
    law%torque_value = torque
    law%body_fixed = body_fixed
    allocate (law%loads(1))
  end function new_constant_load

  pure subroutine constant_evaluate(self, t, frames, scalars, contacts, status)
    class(constant_load_t), intent(inout) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    type(status_t), intent(inout) :: status
    associate (unused_t => t, unused_s => scalars, unused_c => contacts, unused_st => status)
    end associate
    if (self%body_fixed) then
      self%loads(1) = frame_load_t(self%frame, matmul(frames(self%frame)%rot, self%force_value), &
                                   matmul(frames(self%frame)%rot, self%torque_value))
    else
      self%loads(1) = frame_load_t(self%frame, self%force_value, self%torque_value)
    end if
  end subroutine constant_evaluate

  !> The air's drag on the body of `frame` at its centre of mass `centre`
  !> (m, the frame's own axes): drag_area C_d A (m^2), the air's density
  !> (kg/m^3) and velocity `wind` (m/s, world).
  function new_air_drag(name, frame, centre, drag_area, density, wind, status) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame
    real(wp), intent(in) :: centre(3), drag_area, density, wind(3)
    type(status_t), intent(inout) :: status
    type(air_drag_t) :: law
    law%name = name
    law%frame = frame
    law%centre = centre
    law%drag_area = drag_area
    law%density = density
    law%wind = wind
    allocate (law%loads(1))
    call check_coefficient(name, 'drag area C_d A', drag_area, 'm^2', status)
    call check_coefficient(name, 'air density', density, 'kg/m^3', status)
    if (.not. all(abs(wind) < huge(1.0_wp))) call set_status(status, STATUS_INVALID_INPUT, 'force law '''// &
      name//''': the wind must be finite')
  end function new_air_drag

  !> F = -1/2 rho C_d A |w| w at the centre S: the force, and its moment
  !> arm x F about the frame's origin.
  pure subroutine air_drag_evaluate(self, t, frames, scalars, contacts, status)
    class(air_drag_t), intent(inout) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    type(status_t), intent(inout) :: status
    real(wp) :: arm(3), f(3)
    associate (unused_t => t, unused_s => scalars, unused_c => contacts, unused_st => status)
    end associate
    associate (body => frames(self%frame))
      arm = matmul(body%rot, self%centre)
      f = air_drag_force(body%v + cross(body%omega, arm), self%drag_area, self%density, self%wind)
      self%loads(1) = force_at(self%frame, arm, f)
    end associate
  end subroutine air_drag_evaluate

  !> The air's drag F = -1/2 rho C_d A |w| w on a body moving at `velocity`
  !> (m/s, world), w = velocity - wind its velocity relative to the air: the
  !> one law of air_drag_t and of the point mass (kinetostatics_point_mass).
  pure function air_drag_force(velocity, drag_area, density, wind) result(f)
    real(wp), intent(in) :: velocity(3), drag_area, density, wind(3)
    real(wp) :: f(3), w(3)
    w = velocity - wind
    f = -0.5_wp*density*drag_area*norm2(w)*w
  end function air_drag_force
end module kinetostatics_force_laws
