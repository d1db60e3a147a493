!> The equations of motion of a chain or tree of bodies in linear time
!> (kinetostatics_mechanism): the passes around the articulated-body
!> recursion of kinetostatics_tree (its module comment gives the method and
!> when the mechanism takes it).
!>
!> Per right-hand side: the positions (the closure, as in the dense path);
!> every joint's motion subspace S_b at rest, one velocity pass per speed
!> over its joint's elements only (its blocks' closure solved); the
!> velocities, the laws, Q_bar0 (an acceleration pass at s' = 0 and the
!> inverse dynamics) as in the dense path; the recursion; and the inverse
!> dynamics at s', whose cut forces give every contact's normal force
!> (the dense path's N0 + G s', the same linear map of s'). All O(n).
submodule (kinetostatics_mechanism) kinetostatics_mechanism_tree
  use kinetostatics_tree, only: articulated_solve, spatial_inertia
  implicit none (type, external)

contains

  !> s' (qdd), and in the workspace q'' (`qdd`), Q_bar0 (`bias`), the normal
  !> forces (`normal`) and the state at (q, s, s') with the explicit laws'
  !> loads (kinetostatics_mechanism_dynamics' dynamics, for a tree: M, G and
  !> N0 are not formed).
  module procedure tree_dynamics
    real(wp) :: mass, s(3), inertia_w(3, 3)
    integer :: k, b, m, failed
    qdd = 0
    call self%set_positions(work, q, status)
    if (.not. status%ok()) return
    call rest_velocities(work%frames, work%scalars)
    do k = 1, size(self%tree%speed)
      call subspace_column(self, work, k)
    end do
    call self%set_velocities(work, qd)
    call bias_forces(self, work, t, status)
    if (.not. status%ok()) return
    associate (w => work%tree)
      do b = 1, self%tree%n_bodies
        w%origin(:, b) = work%frames(self%tree%frame(b))%r
        w%inertia(:, :, b) = 0
        do m = self%tree%mass_start(b), self%tree%mass_start(b + 1) - 1
          call work%elements(self%tree%mass(m))%e%world_inertia(mass, s, inertia_w)
          call spatial_inertia(mass, s, inertia_w, w%inertia(:, :, b))
        end do
      end do
      call articulated_solve(self%tree, w, work%bias, work%qdd, failed)
    end associate
    if (failed > 0) then
      call no_inertia(self, failed, status)
      return
    end if
    qdd = work%qdd
    call self%set_accelerations(work, qdd)
    call self%inverse_dynamics(work, .true., .true., LOADS_EXPLICIT)
    call self%normal_forces(work, work%lambda, work%normal)
  end procedure tree_dynamics

  !> Column k of the motion subspaces (kinetostatics_tree): at rest, the
  !> twist of its joint's body for a unit rate of its speed, the closure of
  !> the blocks it touches solved; the state back at rest afterwards.
  subroutine subspace_column(self, work, k)
    class(mechanism_t), intent(in) :: self
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: k
    integer :: p, speed, first, last, body
    associate (tree => self%tree)
      speed = self%q(self%speeds(tree%speed(k)))
      body = tree%frame(tree%column_body(k))
      first = tree%touched_start(k)
      last = tree%touched_start(k + 1) - 1
      work%scalars(speed)%qd = 1
      do p = tree%pass_start(k), tree%pass_start(k + 1) - 1
        call work%elements(tree%pass(p))%e%velocity(work%frames, work%scalars)
      end do
      if (last >= first) then
        call work%blocks%solve_rates(self%nd > 0, self%rows, self%unknowns, work%work_x, work%scalars, .true., &
                                     tree%touched(first:last))
        do p = tree%second_start(k), tree%second_start(k + 1) - 1
          call work%elements(tree%second(p))%e%velocity(work%frames, work%scalars)
        end do
      end if
      work%tree%subspace(1:3, k) = work%frames(body)%omega
      work%tree%subspace(4:6, k) = work%frames(body)%v
      ! back to rest: the sources and every output the passes wrote
      work%scalars(speed)%qd = 0
      if (last >= first) call work%blocks%rest_rates(self%unknowns, work%scalars, .true., tree%touched(first:last))
      call rest_outputs(self%reach, tree%pass, tree%pass_start(k), tree%pass_start(k + 1) - 1, work%frames, &
                        work%scalars)
      call rest_outputs(self%reach, tree%second, tree%second_start(k), tree%second_start(k + 1) - 1, work%frames, &
                        work%scalars)
    end associate
  end subroutine subspace_column
end submodule kinetostatics_mechanism_tree
