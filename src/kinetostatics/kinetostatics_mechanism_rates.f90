!> The mechanism's passes and rates (kinetostatics_mechanism): the element
!> passes, the rate solver, inverse dynamics, normal forces and the laws.
!>
!> Velocity-level constraints (rolling, thesis (3.85); METHOD-PART2 A.3):
!> outputs c of constraint elements that must vanish (e.g. the tangential slip
!> of contact_rolling), with as many dependent rates sigma' among the
!> coordinates. The coordinates q are all integrated; the independent rates,
!> the speeds s, are the rest: q' = B(q) s, so the ODE state is [q, s]. At
!> velocity level the unknown rates x = [beta'; sigma'] solve the combined
!> linear system [g'; c] = 0 with the matrix J_x of (3.21) extended by the
!> sigma columns (one velocity pass per column), at acceleration level
!> [g''; c'] = 0 with the same matrix, and the cut forces [lambda; mu] =
!> -J_x^-T [Q_beta; Q_sigma] (mu: the static friction of rolling).
!> Kinematic coordinates (set_kinematic) are integrated coordinates whose rates
!> an element computes itself in its velocity pass (the pose of a body under a
!> velocity-level contact, contact_velocity_level): they are neither speeds nor
!> solved. Without either, s = q' and everything is as before.
!>
!> Loads: gravity acts in the mass elements (kinetostatics_mass); every other
!> load is a force law (kinetostatics_force_law), evaluated once per state with
!> the frames, scalars and contact kinematics (kinetostatics_contact).
submodule (kinetostatics_mechanism) kinetostatics_mechanism_rates
  implicit none (type, external)

contains

  !> Every element but the record-only ones (record_pass).
  module procedure position_pass
    integer :: k
    work%evaluation = work%evaluation + 1
    do k = 1, self%n_elements
      if (work%elements(k)%e%record_only) cycle
      call work%elements(k)%e%position(work%frames, work%scalars, status)
      if (.not. status%ok()) return
    end do
  end procedure position_pass

  !> The record-only elements (element_t) at the current positions, which
  !> the position pass left as they are: their outputs for a record.
  module procedure record_pass
    integer :: k
    do k = 1, self%n_elements
      if (.not. work%elements(k)%e%record_only) cycle
      call work%elements(k)%e%position(work%frames, work%scalars, status)
      if (.not. status%ok()) return
    end do
  end procedure record_pass

  module procedure velocity_pass
    integer :: k
    do k = 1, self%n_elements
      call work%elements(k)%e%velocity(work%frames, work%scalars)
    end do
  end procedure velocity_pass

  module procedure acceleration_pass
    integer :: k
    do k = 1, self%n_elements
      call work%elements(k)%e%acceleration(work%frames, work%scalars)
    end do
  end procedure acceleration_pass

  !> Clears all forces, puts the cut forces lambda on the closure measurements
  !> (and mu, a component, on the rate constraints' outputs) from the workspace
  !> and its laws'
  !> loads selected by `loads` (LOADS_*) on their frames, and runs the elements
  !> backwards.
  module procedure force_pass
    integer :: k
    do k = 1, self%n_frames
      work%frames(k)%torque = 0
      work%frames(k)%force = 0
    end do
    work%scalars%force = 0
    do k = 1, self%r
      work%scalars(self%closure(k))%force = work%lambda(k)
    end do
    do k = 1, self%nd
      work%scalars(self%rate_outputs(k))%force = work%mu(k)
    end do
    select case (loads)
    case (LOADS_NONE)
    case (LOADS_EXPLICIT, LOADS_ALL)
      do k = 1, self%n_laws
        if (.not. work%laws(k)%law%active) cycle
        if (work%laws(k)%law%scaled .and. loads == LOADS_EXPLICIT) cycle
        call put_loads(self, work, k, work%law_factor(k))
      end do
    case default
      call put_loads(self, work, loads, 1.0_wp)
    end select
    do k = self%n_elements, 1, -1
      call work%elements(k)%e%force(work%frames, work%scalars, inertia, applied)
    end do
  end procedure force_pass

  subroutine put_loads(self, work, k, factor)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: k
    real(wp), intent(in) :: factor
    integer :: i
    associate (loads => work%laws(k)%law%loads)
      do i = 1, size(loads)
        associate (fr => work%frames(loads(i)%frame))
          fr%force = fr%force + factor*loads(i)%force
          fr%torque = fr%torque + factor*loads(i)%torque
        end associate
      end do
    end associate
  end subroutine put_loads

  !> Sets the speeds s (positions already set, by set_positions with this
  !> workspace): the rates of the speed coordinates, then beta' (3.30) and the
  !> dependent rates sigma' from [g'; c] = 0; the workspace's `rates` gets q' of every
  !> coordinate (kinematic ones from their elements). Without rate
  !> constraints and kinematic coordinates s = q'.
  module procedure set_velocities
    call set_rates(self, work, s, 1)
  end procedure set_velocities

  !> Sets s' (velocities already set): beta'' (3.31) and sigma'' from [g''; c'] = 0.
  module procedure set_accelerations
    call set_rates(self, work, sd, 2)
  end procedure set_accelerations

  !> Level 1 (velocities) or 2 (accelerations) of the above. The two levels
  !> are written out (no internal procedures: gfortran called them, ~800,000
  !> times in a default run).
  subroutine set_rates(self, work, given, level)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: given(:)
    integer, intent(in) :: level
    integer :: k
    if (level == 1) then
      do k = 1, self%ns
        work%scalars(self%q(self%speeds(k)))%qd = given(k)
      end do
      do k = 1, self%r
        work%scalars(self%beta(k))%qd = 0
      end do
      do k = 1, self%nd
        work%scalars(self%sigma(k))%qd = 0
      end do
      call self%velocity_pass(work)
    else
      do k = 1, self%ns
        work%scalars(self%q(self%speeds(k)))%qdd = given(k)
      end do
      do k = 1, self%r
        work%scalars(self%beta(k))%qdd = 0
      end do
      do k = 1, self%nd
        work%scalars(self%sigma(k))%qdd = 0
      end do
      call self%acceleration_pass(work)
    end if
    if (self%r + self%nd > 0) then
      ! the second pass only over the elements the unknown rates reach: the
      ! others' inputs are those of the first pass, so are their outputs
      if (self%nd == 0) then
        if (level == 1) then
          do k = 1, self%r
            work%work_r(k) = work%scalars(self%closure(k))%qd
          end do
        else
          do k = 1, self%r
            work%work_r(k) = work%scalars(self%closure(k))%qdd
          end do
        end if
        call work%blocks%solve(.false., work%work_r, .false.)
        if (level == 1) then
          do k = 1, self%r
            work%scalars(self%beta(k))%qd = -work%work_r(k)
          end do
        else
          do k = 1, self%r
            work%scalars(self%beta(k))%qdd = -work%work_r(k)
          end do
        end if
      else
        if (level == 1) then
          do k = 1, self%r
            work%work_x(k) = work%scalars(self%closure(k))%qd
          end do
          do k = 1, self%nd
            work%work_x(self%r + k) = work%scalars(self%rate_outputs(k))%qd
          end do
        else
          do k = 1, self%r
            work%work_x(k) = work%scalars(self%closure(k))%qdd
          end do
          do k = 1, self%nd
            work%work_x(self%r + k) = work%scalars(self%rate_outputs(k))%qdd
          end do
        end if
        call work%blocks%solve(.true., work%work_x, .false.)
        if (level == 1) then
          do k = 1, self%r
            work%scalars(self%beta(k))%qd = -work%work_x(k)
          end do
          do k = 1, self%nd
            work%scalars(self%sigma(k))%qd = -work%work_x(self%r + k)
          end do
        else
          do k = 1, self%r
            work%scalars(self%beta(k))%qdd = -work%work_x(k)
          end do
          do k = 1, self%nd
            work%scalars(self%sigma(k))%qdd = -work%work_x(self%r + k)
          end do
        end if
      end if
      if (level == 1) then
        do k = 1, size(self%unknowns_pass)
          call work%elements(self%unknowns_pass(k))%e%velocity(work%frames, work%scalars)
        end do
      else
        do k = 1, size(self%unknowns_pass)
          call work%elements(self%unknowns_pass(k))%e%acceleration(work%frames, work%scalars)
        end do
      end if
    end if
    if (level == 1) then
      do k = 1, self%f
        work%rates(k) = work%scalars(self%q(k))%qd
      end do
    end if
  end subroutine set_rates

  !> Generalized forces at the speeds (into the workspace's gq) with the loops and rate
  !> constraints in equilibrium: lambda = -J_beta^-T Q^_beta (3.32)-(3.33), or
  !> [lambda; mu] = -J_x^-T [Q^_beta; Q^_sigma]. `loads` selects the laws'
  !> loads (LOADS_*).
  module procedure inverse_dynamics
    integer :: k
    work%lambda = 0
    work%mu = 0
    call self%force_pass(work, inertia, applied, loads)
    if (self%nd > 0) then
      do k = 1, self%r
        work%work_x(k) = work%scalars(self%beta(k))%force
      end do
      do k = 1, self%nd
        work%work_x(self%r + k) = work%scalars(self%sigma(k))%force
      end do
      call work%blocks%solve(.true., work%work_x, .true.)
      work%lambda = -work%work_x(1:self%r)
      work%mu = -work%work_x(self%r + 1:)
      call self%force_pass(work, inertia, applied, loads)
    else if (self%r > 0) then
      do k = 1, self%r
        work%lambda(k) = work%scalars(self%beta(k))%force
      end do
      call work%blocks%solve(.false., work%lambda, .true.)
      work%lambda = -work%lambda
      call self%force_pass(work, inertia, applied, loads)
    end if
    do k = 1, self%ns
      work%gq(k) = work%scalars(self%q(self%speeds(k)))%force
    end do
  end procedure inverse_dynamics

  !> Normal force of each contact after an inverse-dynamics pass (rules in
  !> kinetostatics_contact).
  module procedure normal_forces
    integer :: k
    do k = 1, size(self%contacts)
      associate (c => self%contacts(k))
        if (c%normal_rule == NORMAL_CUT_FORCE) then
          n(k) = c%normal_sign*lambda(c%normal_row)
        else
          associate (fr => work%frames(c%normal_frame))
            n(k) = -c%normal_sign*dot_product(fr%rot(:, 3), fr%force)
          end associate
        end if
      end associate
    end do
  end procedure normal_forces

  !> With positions and velocities set: every contact's kinematics, every
  !> active law's loads (scaled laws: per unit |N|) and unit power, and the
  !> laws' root functions.
  module procedure evaluate_laws
    integer :: k, i
    real(wp) :: p
    if (any(work%dims /= self%workspace_dims)) call self%prepare_workspace(work)
    work%evaluation = work%evaluation + 1
    do k = 1, size(self%contacts)
      call contact_kinematics(self%contacts(k), work%frames, work%contact_states(k))
    end do
    do k = 1, self%n_laws
      associate (law => work%laws(k)%law)
        p = 0
        if (law%active) then
          call law%evaluate(t, work%frames, work%scalars, work%contact_states, status)
          if (.not. status%ok()) then
            call prefix_status(status, 'force law '''//law%name//'''')
            return
          end if
          do i = 1, size(law%loads)
            associate (ld => law%loads(i), fr => work%frames(law%loads(i)%frame))
              p = p + dot_product(ld%force, fr%v) + dot_product(ld%torque, fr%omega)
            end associate
          end do
        end if
        work%unit_power(k) = p
        if (self%law_root_start(k + 1) > self%law_root_start(k)) &
          call law%roots(t, work%frames, work%scalars, work%contact_states, &
                         work%law_roots(self%law_root_start(k):self%law_root_start(k + 1) - 1))
      end associate
    end do
  end procedure evaluate_laws

  !> Force of law k at the last evaluation with this workspace (its first
  !> load, i.e. on body B for a contact law), N.
  module procedure law_force
    associate (unused => self)
    end associate
    force = 0
    if (work%laws(k)%law%active) force = work%law_factor(k)*work%laws(k)%law%loads(1)%force
  end procedure law_force

  !> Kinetic and potential energy of all mass elements at the current state (J).
  module procedure energy
    real(wp) :: t, v
    integer :: k
    kinetic = 0
    potential = 0
    do k = 1, self%n_elements
      call work%elements(k)%e%energy(work%frames, t, v)
      kinetic = kinetic + t
      potential = potential + v
    end do
  end procedure energy
end submodule kinetostatics_mechanism_rates
