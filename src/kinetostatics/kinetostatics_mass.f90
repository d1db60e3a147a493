!> The mass element (thesis 3.2.4), a leaf element with its d'Alembert forces
!> (3.23) and gravity: gravity is applied here, once per mass; every other load
!> is a force law (kinetostatics_force_law).
!>
!> Mass element on frame K with mass m, inertia tensor Theta about the centre of
!> mass S (in K's coordinates) and S at s = R s_local from K's origin:
!>     f   = -m (a + alpha x s + omega x (omega x s))                     (3.23)
!>     tau = -(Theta_w alpha + omega x Theta_w omega) + s x f,  Theta_w = R Theta R^T
!> plus, when applied forces are on, the weight m g at S (tau += s x m g).
!> The d'Alembert wrench's power is -dT/dt and the weight's -dV/dt (the test
!> checks both), which is what makes the inverse-dynamics residuals right.
module kinetostatics_mass
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_vector, only: cross
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t
  implicit none (type, external)
  private
  public :: mass_element_t, new_mass_element

  type, extends(element_t) :: mass_element_t
    integer :: frame = 0
    real(wp) :: mass = 0                  ! kg
    real(wp) :: inertia(3, 3) = 0         ! kg m^2, about S, K coordinates
    real(wp) :: com(3) = 0                ! m, S in K coordinates
    real(wp) :: gravity(3) = 0            ! m/s^2
    ! the last position's R; s = R s_local and Theta_w (world) from it, made
    ! by the first force map after the position (`current`): most position
    ! passes are the closure's Newton iterates, never followed by a force pass
    real(wp) :: rot(3, 3) = 0
    logical :: current = .false.
    real(wp) :: s(3) = 0, inertia_w(3, 3) = 0
  contains
    procedure :: position => mass_position
    procedure :: velocity => mass_nothing
    procedure :: acceleration => mass_nothing
    procedure :: force => mass_force
    procedure :: energy => mass_energy
    procedure :: links => mass_links
    procedure :: world_inertia => mass_world_inertia
    procedure :: mass_frame => mass_mass_frame
    procedure :: mass_properties => mass_mass_properties
  end type mass_element_t

contains

  !> Links for kinetostatics_closure_blocks (element_links_t).
  pure subroutine mass_links(self, links)
    class(mass_element_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame], [integer ::], [integer ::], [integer ::])
  end subroutine mass_links

  !> Checks m > 0 and Theta symmetric positive semidefinite with the triangle
  !> inequalities of principal moments (a point mass, Theta = 0, is allowed).
  function new_mass_element(name, frame, mass, inertia, com, gravity, status) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame
    real(wp), intent(in) :: mass, inertia(3, 3), com(3), gravity(3)
    type(status_t), intent(inout) :: status
    type(mass_element_t) :: e
    real(wp) :: tr, scale
    character(len=24) :: text
    e%name = name
    e%frame = frame
    e%mass = mass
    e%inertia = inertia
    e%com = com
    e%gravity = gravity
    write (text, '(es12.5)') mass
    if (.not. (mass > 0) .or. mass > huge(mass)) then
      call set_status(status, STATUS_INVALID_INPUT, 'mass element '''//name//''': mass = '// &
                      trim(adjustl(text))//' kg; it must be positive and finite')
      return
    end if
    scale = max(maxval(abs(inertia)), tiny(1.0_wp))
    tr = inertia(1, 1) + inertia(2, 2) + inertia(3, 3)
    if (maxval(abs(inertia - transpose(inertia))) > 1e-12_wp*scale .or. &
        minval([inertia(1, 1), inertia(2, 2), inertia(3, 3)]) < 0 .or. &
        2*maxval([inertia(1, 1), inertia(2, 2), inertia(3, 3)]) > tr*(1 + 1e-12_wp) .or. &
        .not. all(abs(inertia) <= huge(inertia))) then
      call set_status(status, STATUS_INVALID_INPUT, 'mass element '''//name//''': the inertia tensor '// &
        'must be symmetric with non-negative moments obeying the triangle inequality (I_k <= I_l + I_m)')
    end if
  end function new_mass_element

  pure subroutine mass_position(self, frames, scalars, status)
    class(mass_element_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    associate (unused => scalars, unused_status => status)
    end associate
    self%rot = frames(self%frame)%rot
    self%current = .false.
  end subroutine mass_position

  !> s and Theta_w at the last position.
  pure subroutine world_geometry(self, s, inertia_w)
    class(mass_element_t), intent(in) :: self
    real(wp), intent(out) :: s(3), inertia_w(3, 3)
    s = matmul(self%rot, self%com)
    inertia_w = matmul(self%rot, matmul(self%inertia, transpose(self%rot)))
  end subroutine world_geometry

  !> m, s = R s_local and Theta_w at the last position (the mechanism's mass
  !> matrix from the frames' partial twists: M = sum m p_i . p_j + alpha_i . Theta_w alpha_j).
  pure subroutine mass_world_inertia(self, mass, s, inertia_w)
    class(mass_element_t), intent(inout) :: self
    real(wp), intent(out) :: mass, s(3), inertia_w(3, 3)
    if (.not. self%current) then
      call world_geometry(self, self%s, self%inertia_w)
      self%current = .true.
    end if
    mass = self%mass
    s = self%s
    inertia_w = self%inertia_w
  end subroutine mass_world_inertia

  pure integer function mass_mass_frame(self) result(frame)
    class(mass_element_t), intent(in) :: self
    frame = self%frame
  end function mass_mass_frame

  pure subroutine mass_mass_properties(self, mass, com, inertia, gravity)
    class(mass_element_t), intent(in) :: self
    real(wp), intent(out) :: mass, com(3), inertia(3, 3), gravity(3)
    mass = self%mass
    com = self%com
    inertia = self%inertia
    gravity = self%gravity
  end subroutine mass_mass_properties

  pure subroutine mass_nothing(self, frames, scalars)
    class(mass_element_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (unused => self, unused_f => frames, unused_s => scalars)
    end associate
  end subroutine mass_nothing

  pure subroutine mass_force(self, frames, scalars, inertia, applied)
    class(mass_element_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3), t(3)
    associate (unused => scalars)
    end associate
    if (.not. self%current) then
      call world_geometry(self, self%s, self%inertia_w)
      self%current = .true.
    end if
    associate (k => frames(self%frame), s => self%s)
      if (inertia) then
        if (any(k%omega /= 0)) then
          f = -self%mass*(k%a + cross(k%alpha, s) + cross(k%omega, cross(k%omega, s)))     ! (3.23)
          t = -(matmul(self%inertia_w, k%alpha) + cross(k%omega, matmul(self%inertia_w, k%omega))) &
              + cross(s, f)
        else
          ! at rest (mass-matrix columns): the same without the zero omega terms
          f = -self%mass*(k%a + cross(k%alpha, s))
          t = -matmul(self%inertia_w, k%alpha) + cross(s, f)
        end if
        k%force = k%force + f
        k%torque = k%torque + t
      end if
      if (applied) then
        f = self%mass*self%gravity
        k%force = k%force + f
        k%torque = k%torque + cross(s, f)
      end if
    end associate
  end subroutine mass_force

  !> T = m |v_S|^2/2 + omega.Theta_w omega/2, V = -m g.r_S.
  pure subroutine mass_energy(self, frames, kinetic, potential)
    class(mass_element_t), intent(in) :: self
    type(frame_state_t), intent(in) :: frames(:)
    real(wp), intent(out) :: kinetic, potential
    real(wp) :: vs(3), s(3), inertia_w(3, 3)
    if (self%current) then
      s = self%s
      inertia_w = self%inertia_w
    else
      call world_geometry(self, s, inertia_w)
    end if
    associate (k => frames(self%frame))
      vs = k%v + cross(k%omega, s)
      kinetic = 0.5_wp*self%mass*dot_product(vs, vs) + &
                0.5_wp*dot_product(k%omega, matmul(inertia_w, k%omega))
      potential = -self%mass*dot_product(self%gravity, k%r + s)
    end associate
  end subroutine mass_energy
end module kinetostatics_mass
