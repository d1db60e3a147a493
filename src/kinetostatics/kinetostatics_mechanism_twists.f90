!> The mechanism's mass matrix and normal-force maps from the partial
!> twists (kinetostatics_mechanism).
!>
!> M and G from the partial twists: every frame's twist is linear in the
!> speeds, so with the velocities zero the acceleration state of s' = e_i
!> (the closure solved) is column i of the partial twists (alpha, a) of the
!> mass elements' frames (and of the scaled laws' load frames: `tracked`).
!> The inertial wrench of a mass per unit s'_i is (3.23) at rest and M(j, i)
!> = -(twist_j . wrench_i) = sum m p_j . p_i + alpha_j . Theta_w alpha_i (p
!> the centre of mass's acceleration), so one acceleration pass per speed
!> over the elements it moves (kinetostatics_closure_blocks,
!> build_mass_columns) replaces the column's two force passes. Every normal
!> force is linear in the wrenches W at the tracked frames, N_c = -normal_sign
!> nu_c . W (twist_normal_forces: the cut forces through J_x^-T by one solve
!> per contact, a frame's force through one pass moving the frame along its
!> normal), which gives G = N per unit s' and, with the scaled laws' unit
!> loads as W, H and P (the loads' powers on the speeds' twists). Only the
!> mass elements have inertia (kinetostatics_mass). A mechanism with an
!> element of unknown links forms M and G by the inverse-dynamics pass per
!> speed instead (s' = e_i, velocities zero, applied forces off: -M e_i) and
!> P and H by one per scaled law, as does a scaled law with a load on a frame
!> that is not tracked.
submodule (kinetostatics_mechanism) kinetostatics_mechanism_twists
  implicit none (type, external)

contains

  subroutine clear_accelerations(self, work)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer :: k
    do k = 1, self%n_frames
      work%frames(k)%alpha = 0
      work%frames(k)%a = 0
    end do
    work%scalars%qdd = 0
  end subroutine clear_accelerations

  !> M and G from the partial twists of the tracked frames (module comment),
  !> velocities zero: column i of the twists is the acceleration state of
  !> s' = e_i at rest (the closure solved), or equally the velocity state of
  !> s = e_i (velocity_column), the inertial wrench of each mass
  !> per unit s'_i is (3.23) at rest, and M(j, i) = -(twist_j . wrench_i).
  module procedure twist_mass_matrix
    real(wp) :: mass, s(3), inertia_w(3, 3)
    integer :: i, b
    call clear_accelerations(self, work)
    if (self%velocity_columns) then
      do i = self%ns, 1, -1
        call velocity_column(self, work, i)
      end do
      ! back to rest (the normal forces' passes are acceleration maps at rest)
      call rest_outputs(self%reach, self%blocks%mass_pass, self%blocks%mass_pass_start(1), &
                        self%blocks%mass_pass_start(2) - 1, work%frames, work%scalars)
    else
      do i = 1, self%ns
        if (self%blocks%mass_blocked) then
          call unit_column(self, work, i)
        else
          work%work_f = 0
          work%work_f(i) = 1
          call self%set_accelerations(work, work%work_f)
          call keep_twists(self, work%frames, work%twist(:, :, i))
        end if
      end do
      if (.not. self%blocks%mass_blocked) call clear_accelerations(self, work)
    end if
    call clear_sequence(size(work%wrench), work%wrench)
    do b = 1, size(self%masses)
      if (self%mass_slot(b) == 0) cycle   ! a mass on the ground
      call work%elements(self%masses(b))%e%world_inertia(mass, s, inertia_w)
      call add_inertial_wrenches(self%ns, size(self%tracked), self%mass_slot(b), mass, s, inertia_w, work%twist, &
                                 work%wrench)
    end do
    ! M(j, i) = -(twist_j . wrench_i), and its lower triangle, the factor's input
    call symmetric_transposed_product(6*size(self%tracked), self%ns, work%twist, work%wrench, -1.0_wp, &
                                      work%mass, work%chol)
    if (size(self%contacts) > 0) call twist_normal_forces(self, work)
  end procedure twist_mass_matrix

  !> x = 0 for an array passed as its sequence of n elements: one store
  !> loop (an allocatable component of rank 3 set to 0 directly costs a
  !> memset call per column and loop control around it).
  pure subroutine clear_sequence(n, x)
    integer, intent(in) :: n
    real(wp), intent(out) :: x(n)
    x = 0
  end subroutine clear_sequence

  !> The inertial wrenches (torque, force at the frame's origin) of a mass
  !> (m, s = R s_local, Theta_w) on the tracked frame t per unit s'_i: (3.23)
  !> at rest with (alpha, a) = twist(:, t, i), added to wrench(:, t, i).
  pure subroutine add_inertial_wrenches(ns, nt, t, mass, s, inertia_w, twist, wrench)
    integer, intent(in) :: ns, nt, t
    real(wp), intent(in) :: mass, s(3), inertia_w(3, 3), twist(6, nt, ns)
    real(wp), intent(inout) :: wrench(6, nt, ns)
    real(wp) :: f(3)
    integer :: i
    do i = 1, ns
      f = -mass*(twist(4:6, t, i) + cross(twist(1:3, t, i), s))
      wrench(1:3, t, i) = wrench(1:3, t, i) + cross(s, f) - inertia_w(:, 1)*twist(1, t, i) &
                          - inertia_w(:, 2)*twist(2, t, i) - inertia_w(:, 3)*twist(3, t, i)
      wrench(4:6, t, i) = wrench(4:6, t, i) + f
    end do
  end subroutine add_inertial_wrenches

  !> Column i of the twists by passes over the elements a unit s'_i moves
  !> and the blocks it moves (kinetostatics_closure_blocks,
  !> build_mass_columns): one acceleration pass, the touched blocks' solve,
  !> a second pass over what their unknowns move. Pass i of the sequence of
  !> clear_before.
  subroutine unit_column(self, work, i)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: i
    integer :: p, speed, first, last
    ! index bounds, not associated slices: descriptors cost more than the
    ! work for the usual column that touches no block
    speed = self%q(self%speeds(i))
    first = self%blocks%touched_start(i)
    last = self%blocks%touched_start(i + 1) - 1
    call clear_before(self, work, i)
    work%scalars(speed)%qdd = 1
    do p = self%blocks%mass_pass_start(i), self%blocks%mass_pass_start(i + 1) - 1
      call work%elements(self%blocks%mass_pass(p))%e%acceleration(work%frames, work%scalars)
    end do
    if (last >= first) then
      call work%blocks%solve_rates(self%nd > 0, self%rows, self%unknowns, work%work_x, work%scalars, .false., &
                                   self%blocks%touched(first:last))
      call accelerate(self, work, self%blocks%second_pass(self%blocks%second_pass_start(i): &
                                                    self%blocks%second_pass_start(i + 1) - 1))
    end if
    call keep_twists(self, work%frames, work%twist(:, :, i))
    ! the sources back to rest (the outputs: clear_before)
    work%scalars(speed)%qdd = 0
    if (last >= first) call work%blocks%rest_rates(self%unknowns, work%scalars, .false., self%blocks%touched(first:last))
  end subroutine unit_column

  !> Column i of the twists when no column touches a block: the velocity
  !> state of s = e_i (the other rates zero) is the partial twist J e_i, the
  !> acceleration state of s' = e_i at rest (unit_column) by the velocity
  !> maps of the same pass. The columns run from the last to the first
  !> after a state at rest (build_velocity_clears); `rates` (q' of the
  !> state, read by the integrator) is not touched.
  subroutine velocity_column(self, work, i)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: i
    integer :: p, speed
    speed = self%q(self%speeds(i))
    if (self%velocity_clear_start(i + 1) > self%velocity_clear_start(i)) &
      call rest_outputs(self%reach, self%velocity_clear, self%velocity_clear_start(i), &
                        self%velocity_clear_start(i + 1) - 1, work%frames, work%scalars)
    work%scalars(speed)%qd = 1
    do p = self%blocks%mass_pass_start(i), self%blocks%mass_pass_start(i + 1) - 1
      call work%elements(self%blocks%mass_pass(p))%e%velocity(work%frames, work%scalars)
    end do
    call keep_velocity_twists(self, work%frames, work%twist(:, :, i))
    work%scalars(speed)%qd = 0
  end subroutine velocity_column

  !> The tracked frames' (omega, v) (keep_twists of a velocity state).
  subroutine keep_velocity_twists(self, frames, twists)
    class(mechanism_t), intent(in) :: self
    type(frame_state_t), intent(in) :: frames(:)
    real(wp), intent(out) :: twists(6, size(self%tracked))
    integer :: t
    !GCC$ unroll 1
    do t = 1, size(self%tracked)
      twists(1:3, t) = frames(self%tracked(t))%omega
      twists(4:6, t) = frames(self%tracked(t))%v
    end do
  end subroutine keep_velocity_twists

  !> The normal-force map of every contact, N = -normal_sign nu_c . W for
  !> any wrenches W (torque, force) at the tracked frames (inertial or
  !> applied), and G from it (module comment). With x = [lambda; mu] =
  !> -J_x^-T Q_x the cut forces of W, Q_x(k) = twist_k . W the generalized
  !> forces on the unknowns (their open partial twists), a row vector r
  !> gives r . x = -(J_x^-1 r) . Q_x: so nu_c = n_c - sum_k y_k twist_k with
  !> y = J_x^-1 r_c, where for N = normal_sign lambda of a row, n_c = 0 and
  !> r_c = -e_row, and for N = -normal_sign z_F . f_F, n_c is the twist of
  !> the motion of F along z_F (the tracked frames it carries) and r_c the
  !> rows' rates of that motion (z_F . f_F is the power of W and of the cut
  !> forces on it). Velocities and accelerations zero.
  subroutine twist_normal_forces(self, work)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp) :: factor
    integer :: i, k, l, c, f, nx, step
    nx = self%r + self%nd
    step = 0
    if (self%blocks%mass_blocked) step = self%ns
    do l = 1, size(self%moving_unknowns)   ! the other unknowns move no tracked frame
      k = self%moving_unknowns(l)
      step = step + 1
      call clear_before(self, work, step)
      work%scalars(self%unknowns(k))%qdd = 1
      call accelerate(self, work, self%blocks%unknown_pass(self%blocks%unknown_pass_start(k): &
                                                     self%blocks%unknown_pass_start(k + 1) - 1))
      call keep_twists(self, work%frames, work%unknown_twist(:, :, l))
      work%scalars(self%unknowns(k))%qdd = 0
    end do
    l = 0
    do c = 1, size(self%contacts)
      associate (contact => self%contacts(c))
        if (contact%normal_rule == NORMAL_CUT_FORCE) then
          work%nu(:, :, c) = 0
          work%work_x = 0
          work%work_x(contact%normal_row) = -1
        else
          l = l + 1
          f = contact%normal_frame
          step = step + 1
          call clear_before(self, work, step)
          work%frames(f)%a = work%frames(f)%rot(:, 3)
          call accelerate(self, work, self%blocks%normal_pass(self%blocks%normal_pass_start(l): &
                                                        self%blocks%normal_pass_start(l + 1) - 1))
          call keep_twists(self, work%frames, work%nu(:, :, c))
          do k = 1, nx
            work%work_x(k) = work%scalars(self%rows(k))%qdd
          end do
          work%frames(f)%a = 0
        end if
      end associate
      if (size(self%moving_unknowns) == 0) cycle
      call work%blocks%solve(self%nd > 0, work%work_x, .false.)
      do k = 1, size(self%moving_unknowns)
        work%nu(:, :, c) = work%nu(:, :, c) &
                                - work%work_x(self%moving_unknowns(k))*work%unknown_twist(:, :, k)
      end do
    end do
    call transposed_product(6*size(self%tracked), size(self%contacts), self%ns, work%nu, work%wrench, &
                            work%g_mat)
    do c = 1, size(self%contacts)
      factor = -self%contacts(c)%normal_sign   ! +-1: the products are exact
      do i = 1, self%ns
        work%g_mat(c, i) = factor*work%g_mat(c, i)
      end do
    end do
  end subroutine twist_normal_forces

  !> P and H (module comment) of the scaled laws from the twists: the
  !> generalized forces of law k's unit loads are the powers of its wrenches
  !> on the speeds' twists, the normal forces -normal_sign nu_c . wrenches
  !> (twist_normal_forces); a law with a load on a frame that is not tracked
  !> (nor the ground) gets its inverse-dynamics pass.
  module procedure twist_unit_loads
    integer :: k, j, t, c
    logical :: tracked
    do k = 1, size(self%scaled_laws)
      work%load_wrench = 0
      tracked = .true.
      associate (loads => work%laws(self%scaled_laws(k))%law%loads)
        do j = 1, size(loads)
          if (loads(j)%frame == 1) cycle   ! the ground: no power
          t = self%tracked_slot(loads(j)%frame)
          if (t == 0) then
            tracked = .false.
            exit
          end if
          work%load_wrench(1:3, t) = work%load_wrench(1:3, t) + loads(j)%torque
          work%load_wrench(4:6, t) = work%load_wrench(4:6, t) + loads(j)%force
        end do
      end associate
      if (.not. tracked) then
        call self%inverse_dynamics(work, .false., .false., self%scaled_laws(k))
        work%p_mat(:, k) = work%gq
        call self%normal_forces(work, work%lambda, work%h_mat(:, k))
        cycle
      end if
      call transposed_product(6*size(self%tracked), self%ns, 1, work%twist, work%load_wrench, &
                              work%p_mat(:, k))
      call transposed_product(6*size(self%tracked), size(self%contacts), 1, work%nu, work%load_wrench, &
                              work%h_mat(:, k))
      do c = 1, size(self%contacts)
        work%h_mat(c, k) = -self%contacts(c)%normal_sign*work%h_mat(c, k)
      end do
    end do
  end procedure twist_unit_loads

  !> The acceleration maps of the elements `pass`, in order.
  subroutine accelerate(self, work, pass)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: pass(:)
    integer :: p
    do p = 1, size(pass)
      call work%elements(pass(p))%e%acceleration(work%frames, work%scalars)
    end do
  end subroutine accelerate

  !> The tracked frames' (alpha, a). (Here and in clear_before the loops run
  !> a few times: not unrolled, -funroll-loops' remainder dispatch costs more.)
  subroutine keep_twists(self, frames, twists)
    class(mechanism_t), intent(in) :: self
    type(frame_state_t), intent(in) :: frames(:)
    real(wp), intent(out) :: twists(6, size(self%tracked))
    integer :: t
    !GCC$ unroll 1
    do t = 1, size(self%tracked)
      twists(1:3, t) = frames(self%tracked(t))%alpha
      twists(4:6, t) = frames(self%tracked(t))%a
    end do
  end subroutine keep_twists

  !> Before pass `step` of the mass matrix's sequence
  !> (kinetostatics_closure_blocks, build_mass_columns): the accelerations
  !> of the outputs the pass before wrote and this one does not, set to rest.
  subroutine clear_before(self, work, step)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: step
    integer :: p, l, e
    !GCC$ unroll 1
    do p = self%blocks%clear_start(step), self%blocks%clear_start(step + 1) - 1
      e = self%blocks%clear(p)
      !GCC$ unroll 1
      do l = self%reach%frame_out_start(e), self%reach%frame_out_start(e + 1) - 1
        work%frames(self%reach%frame_out(l))%alpha = 0
        work%frames(self%reach%frame_out(l))%a = 0
      end do
      !GCC$ unroll 1
      do l = self%reach%scalar_out_start(e), self%reach%scalar_out_start(e + 1) - 1
        work%scalars(self%reach%scalar_out(l))%qdd = 0
      end do
    end do
  end subroutine clear_before
end submodule kinetostatics_mechanism_twists
