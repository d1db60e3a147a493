!> Linear-time equations of motion for a mechanism whose bodies form a chain
!> or a tree (issue 29, point 3): the articulated-body recursion (Featherstone)
!> on the joints' configuration-dependent motion subspaces, instead of the
!> dense mass matrix M in minimal coordinates (kinetostatics_mechanism_dynamics).
!>
!> Structure (find_tree, at finalize). A body is a frame that carries mass
!> (a tracked frame of the dense path). A unit speed s_k, with the closure
!> blocks its motion touches solved, moves a set T(k) of bodies; the
!> structural sweep of kinetostatics_closure_blocks (reach_of, frame classes)
!> tells whether they all move with one rigid motion. The mechanism is a tree
!> when, for every speed k, the body of T(k) moved by the fewest speeds (its
!> joint's body b(k)) is unique and every other body of T(k) moves rigidly
!> with it; the speeds of one joint move the same bodies; a body's speeds
!> less its joint's are exactly its parent's; each closure block is touched
!> by one joint only (its loop closes inside that joint: a contact's loop in
!> the relative chain of contact_pair); and T(k) is b(k)'s subtree. Then the
!> partial twist of body c per unit s_k is the rigid shift of S_b e_k, S_b the
!> twist of b per unit speed of its own joint at rest (the joint's motion
!> subspace: 6 x k_b, configuration-dependent, the closure of its block
!> solved), so M = sum_b J_b^T I_b J_b has the tree's structure. Anything
!> else (one body, a closed loop across joints, scaled laws, an element of
!> unknown links, the unblocked computation) keeps the dense path.
!>
!> Per right-hand side (kinetostatics_mechanism_tree): S_b by one velocity
!> pass per speed over its joint's elements only (pruned to what feeds b's
!> frame and the rows of its blocks: O(1) per joint), the bias Q_bar0 as in
!> the dense path (one acceleration and one inverse-dynamics pass: O(n)),
!> then `articulated_solve` solves M s' = Q_bar0 in O(n): spatial quantities
!> in world axes about each body frame's origin r_b, twists (omega, v),
!> wrenches (torque, force), the shift of a twist from r_p to r_b
!> v_b = v_p + omega x (r_b - r_p) and its transpose for wrenches and
!> inertias; with p = 0 and c = 0 (the velocity terms are in Q_bar0 and the
!> accelerations are those beyond the s' = 0 state, linear in s'):
!>   backward  IA_b = I_b + sum_c X_c^T (IA_c - U_c D_c^-1 U_c^T) X_c,
!>             U_b = IA_b S_b, D_b = S_b^T U_b, u_b = tau_b - S_b^T pA_b,
!>             pA_b = sum_c X_c^T (pA_c + U_c D_c^-1 u_c);
!>   forward   a'_b = X_b a_p, s'_b = D_b^-1 (u_b - U_b^T a'_b), a_b = a'_b + S_b s'_b.
!> The normal forces then come from the inverse-dynamics pass at s' (the
!> dense path's N0 + G s': the same linear map, evaluated at once).
module kinetostatics_tree
  use base_kinds, only: wp
  use base_vector, only: skew
  use kinetostatics_closure_blocks, only: closure_blocks_t, element_reach_t, reach_of, feeding
  implicit none (type, external)
  private
  public :: tree_t, tree_work_t, find_tree, articulated_solve, spatial_inertia

  !> The tree's structure (find_tree). Bodies in order, parents first; joint
  !> b's speeds speed(speed_start(b):speed_start(b + 1) - 1) (indices of the
  !> speeds 1..ns); column j of the motion subspaces belongs to speed(j) and
  !> has its passes: the first over pass(pass_start(j):pass_start(j + 1) - 1),
  !> the blocks touched(touched_start(j):...) solved, then second(...).
  type :: tree_t
    logical :: active = .false.
    integer :: n_bodies = 0
    integer, allocatable :: frame(:), parent(:), speed_start(:), speed(:), mass_start(:), mass(:)
    integer, allocatable :: column_body(:)   ! the body of each column
    integer, allocatable :: pass_start(:), pass(:), touched_start(:), touched(:), second_start(:), second(:)
  end type tree_t

  !> The recursion's work arrays (one integration's workspace).
  type :: tree_work_t
    real(wp), allocatable :: origin(:, :)        ! (3, bodies): r_b
    real(wp), allocatable :: inertia(:, :, :)    ! (6, 6, bodies): I_b, then IA_b
    real(wp), allocatable :: bias(:, :)          ! (6, bodies): pA_b
    real(wp), allocatable :: subspace(:, :)      ! (6, speeds): S columns (tree order)
    real(wp), allocatable :: u_mat(:, :)         ! (6, speeds): U = IA S
    real(wp), allocatable :: d_factor(:, :, :)   ! (6, 6, bodies): Cholesky factor of D_b (lower)
    real(wp), allocatable :: u_vec(:)            ! (speeds): u
    real(wp), allocatable :: accel(:, :)         ! (6, bodies): a_b
  contains
    procedure :: size_for
  end type tree_work_t

contains

  subroutine size_for(self, tree, ns)
    class(tree_work_t), intent(inout) :: self
    type(tree_t), intent(in) :: tree
    integer, intent(in) :: ns
    integer :: nb
    nb = tree%n_bodies
    if (allocated(self%origin)) deallocate (self%origin, self%inertia, self%bias, self%subspace, self%u_mat, &
                                            self%d_factor, self%u_vec, self%accel)
    allocate (self%origin(3, nb), self%inertia(6, 6, nb), self%bias(6, nb), self%subspace(6, ns), &
              self%u_mat(6, ns), self%d_factor(6, 6, nb), self%u_vec(ns), self%accel(6, nb))
    self%subspace = 0
  end subroutine size_for

  !> The tree of the bodies (module comment), or tree%active false. speeds:
  !> the speeds' scalars; tracked: the body frames (the mass elements'
  !> frames), mass_frames(i) the frame of mass element masses(i).
  subroutine find_tree(tree, reach, blocks, n_frames, n_scalars, speeds, unknowns, rows, tracked, masses, &
                       mass_frames)
    type(tree_t), intent(out) :: tree
    type(element_reach_t), intent(in) :: reach
    type(closure_blocks_t), intent(in) :: blocks
    integer, intent(in) :: n_frames, n_scalars, speeds(:), unknowns(:), rows(:), tracked(:), masses(:), &
      mass_frames(:)
    integer :: ns, nt, nblk, k, b, t, p, j, fewest, n_own
    logical :: moving(n_scalars), live(size(reach%carried)), live_unknowns(size(reach%carried)), &
      changed, frame_wanted(n_frames), row(n_scalars), no_row(n_scalars)
    logical, allocatable :: moves(:, :), moved(:, :), own(:, :)
    integer, allocatable :: classes(:), class_of(:, :), sources(:), body_of(:), order(:), parent_t(:), &
      pass(:), slot(:), moved_by(:)
    ns = size(speeds)
    nt = size(tracked)
    nblk = size(blocks%blocks)
    tree%active = .false.
    tree%n_bodies = 0
    if (.not. (reach%known .and. blocks%mass_blocked) .or. nt < 2 .or. ns < 1) return
    allocate (moves(nt, ns), moved(nblk, ns), own(nt, ns), classes(n_frames), class_of(nt, ns), body_of(ns))
    ! the sweep of each unit speed with the blocks it touches (build_mass_columns' fixpoint)
    do k = 1, ns
      moved(:, k) = .false.
      sources = [speeds(k)]
      do
        call reach_of(reach, sources, n_frames, n_scalars, moving, live, classes=classes)
        changed = .false.
        do b = 1, nblk
          if (moved(b, k) .or. .not. any(moving(rows(blocks%blocks(b)%members)))) cycle
          moved(b, k) = .true.
          changed = .true.
          sources = [sources, unknowns(blocks%blocks(b)%members)]
        end do
        if (.not. changed) exit
      end do
      class_of(:, k) = classes(tracked)
      moves(:, k) = class_of(:, k) /= 0
      if (.not. any(moves(:, k))) return   ! a speed that moves no mass
    end do
    moved_by = [(count(moves(t, :)), t = 1, nt)]
    ! each speed's joint: the body it moves that the fewest speeds move (unique), the others rigidly with it
    do k = 1, ns
      fewest = minval(moved_by, mask=moves(:, k))
      if (count(moves(:, k) .and. moved_by == fewest) /= 1) return
      body_of(k) = findloc(moves(:, k) .and. moved_by == fewest, .true., dim=1)
      if (any(moves(:, k) .and. class_of(:, k) /= class_of(body_of(k), k))) return
    end do
    ! every body has a joint, one joint's speeds move the same bodies, a block belongs to one joint
    own = .false.
    do k = 1, ns
      own(body_of(k), k) = .true.
    end do
    do t = 1, nt
      n_own = count(own(t, :))
      if (n_own < 1 .or. n_own > 6) return
    end do
    do k = 1, ns
      do j = k + 1, ns
        if (body_of(j) == body_of(k)) then
          if (any(moves(:, j) .neqv. moves(:, k))) return
        else
          if (any(moved(:, j) .and. moved(:, k))) return
        end if
      end do
    end do
    ! parents: a body's speeds less its own are exactly one body's (or none: on the ground)
    allocate (parent_t(nt))
    do t = 1, nt
      parent_t(t) = -1
      if (.not. any(moves(t, :) .and. .not. own(t, :))) parent_t(t) = 0
      do p = 1, nt
        if (p == t) cycle
        if (all(moves(p, :) .eqv. (moves(t, :) .and. .not. own(t, :)))) parent_t(t) = p
      end do
      if (parent_t(t) < 0) return
    end do
    ! each speed moves exactly its body's subtree
    do k = 1, ns
      do t = 1, nt
        if (moves(t, k) .neqv. ancestor_or_self(body_of(k), t)) return
      end do
    end do

    ! the tree: bodies by the number of speeds that move them (parents first)
    tree%n_bodies = nt
    order = sort_by_count()
    allocate (slot(nt))
    slot(order) = [(b, b = 1, nt)]
    tree%frame = tracked(order)
    tree%parent = [(0, b = 1, nt)]
    do b = 1, nt
      if (parent_t(order(b)) > 0) tree%parent(b) = slot(parent_t(order(b)))
    end do
    allocate (tree%speed_start(nt + 1), tree%speed(0), tree%mass_start(nt + 1), tree%mass(0))
    do b = 1, nt
      tree%speed_start(b) = size(tree%speed) + 1
      tree%speed = [tree%speed, pack([(k, k = 1, ns)], body_of == order(b))]
      tree%mass_start(b) = size(tree%mass) + 1
      tree%mass = [tree%mass, pack(masses, mass_frames == tree%frame(b))]
    end do
    tree%speed_start(nt + 1) = size(tree%speed) + 1
    allocate (tree%column_body(ns))
    do b = 1, nt
      tree%column_body(tree%speed_start(b):tree%speed_start(b + 1) - 1) = b
    end do
    tree%mass_start(nt + 1) = size(tree%mass) + 1
    ! each column's passes, pruned to what feeds its body's frame (and the rows of its blocks)
    allocate (tree%pass_start(ns + 1), tree%touched_start(ns + 1), tree%second_start(ns + 1))
    allocate (tree%pass(0), tree%touched(0), tree%second(0))
    no_row = .false.
    do j = 1, ns
      k = tree%speed(j)
      b = slot(body_of(k))
      tree%pass_start(j) = size(tree%pass) + 1
      tree%touched_start(j) = size(tree%touched) + 1
      tree%second_start(j) = size(tree%second) + 1
      frame_wanted = .false.
      frame_wanted(tree%frame(b)) = .true.
      sources = [speeds(k)]
      row = .false.
      do p = 1, nblk
        if (.not. moved(p, k)) cycle
        sources = [sources, unknowns(blocks%blocks(p)%members)]
        row(rows(blocks%blocks(p)%members)) = .true.
      end do
      ! first the speed's own motion up to its body and its blocks' rows, then what their unknowns move
      call reach_of(reach, sources(1:1), n_frames, n_scalars, moving, live)
      pass = feeding(reach, live, frame_wanted, row)
      tree%pass = [tree%pass, pass]
      tree%touched = [tree%touched, pack([(p, p = 1, nblk)], moved(:, k))]
      if (size(sources) == 1) cycle
      call reach_of(reach, sources, n_frames, n_scalars, moving, live)
      call reach_of(reach, sources(2:), n_frames, n_scalars, moving, live_unknowns)
      tree%second = [tree%second, feeding(reach, live .and. live_unknowns, frame_wanted, no_row)]
    end do
    tree%pass_start(ns + 1) = size(tree%pass) + 1
    tree%touched_start(ns + 1) = size(tree%touched) + 1
    tree%second_start(ns + 1) = size(tree%second) + 1
    tree%active = .true.
  contains
    logical function ancestor_or_self(a, t)
      integer, intent(in) :: a, t
      integer :: c
      c = t
      ancestor_or_self = .false.
      do while (c > 0)
        if (c == a) then
          ancestor_or_self = .true.
          return
        end if
        c = parent_t(c)
      end do
    end function ancestor_or_self

    function sort_by_count() result(list)
      integer :: list(nt), counts(nt), i, m, tmp
      counts = [(count(moves(i, :)), i = 1, nt)]
      list = [(i, i = 1, nt)]
      do i = 2, nt   ! insertion sort, stable
        m = i
        do while (m > 1)
          if (counts(list(m - 1)) <= counts(list(m))) exit
          tmp = list(m - 1)
          list(m - 1) = list(m)
          list(m) = tmp
          m = m - 1
        end do
      end do
    end function sort_by_count
  end subroutine find_tree

  !> The spatial inertia (twist -> wrench, (omega, v) -> (torque, force),
  !> about the body frame's origin, world axes) of a mass m with centre
  !> s = R s_local from the origin and inertia Theta_w about the centre,
  !> added to inertia: [[Theta_w - m [s]x^2, m [s]x], [-m [s]x, m I]]
  !> (kinetostatics_mechanism_twists, add_inertial_wrenches, with the sign
  !> of -wrench).
  pure subroutine spatial_inertia(mass, s, inertia_w, inertia)
    real(wp), intent(in) :: mass, s(3), inertia_w(3, 3)
    real(wp), intent(inout) :: inertia(6, 6)
    real(wp) :: sx(3, 3)
    integer :: i
    sx = skew(s)
    inertia(1:3, 1:3) = inertia(1:3, 1:3) + inertia_w - mass*matmul(sx, sx)
    inertia(1:3, 4:6) = inertia(1:3, 4:6) + mass*sx
    inertia(4:6, 1:3) = inertia(4:6, 1:3) - mass*sx
    do i = 4, 6
      inertia(i, i) = inertia(i, i) + mass
    end do
  end subroutine spatial_inertia

  !> s' from M s' = tau by the articulated-body recursion (module comment):
  !> w%origin, w%inertia (I_b), w%subspace (S) set; tau and qdd by speed
  !> (1..ns). failed: 0, or the first speed of a joint whose D_b is not
  !> positive definite (no inertia against that joint's motion).
  pure subroutine articulated_solve(tree, w, tau, qdd, failed)
    type(tree_t), intent(in) :: tree
    type(tree_work_t), intent(inout) :: w
    real(wp), intent(in) :: tau(:)
    real(wp), intent(out) :: qdd(:)
    integer, intent(out) :: failed
    real(wp) :: ia(6, 6), y(6, 6), d(6, 6), pa(6), x(6), a(6), shift(6, 6)
    integer :: b, p, i, j, l, first, n
    failed = 0
    w%bias(:, 1:tree%n_bodies) = 0
    do b = tree%n_bodies, 1, -1
      first = tree%speed_start(b)
      n = tree%speed_start(b + 1) - first
      associate (s => w%subspace(:, first:first + n - 1), u => w%u_mat(:, first:first + n - 1), &
                 uv => w%u_vec(first:first + n - 1))
        ia = w%inertia(:, :, b)
        do j = 1, n   ! U = IA S, D = S^T U, u = tau - S^T pA
          do i = 1, 6
            u(i, j) = dot_product(ia(i, :), s(:, j))
          end do
          uv(j) = tau(tree%speed(first + j - 1)) - dot_product(s(:, j), w%bias(:, b))
          do i = 1, n
            d(i, j) = dot_product(s(:, i), u(:, j))
          end do
        end do
        call cholesky_small(n, d, failed)
        if (failed > 0) then
          failed = tree%speed(first + failed - 1)
          return
        end if
        w%d_factor(1:n, 1:n, b) = d(1:n, 1:n)
        p = tree%parent(b)
        if (p == 0) cycle
        ! IA - U D^-1 U^T and pA + U D^-1 u, shifted to the parent's origin
        do i = 1, 6
          y(1:n, i) = u(i, 1:n)
          call cholesky_small_solve(n, d, y(:, i))
        end do
        x(1:n) = uv
        call cholesky_small_solve(n, d, x)
        pa = w%bias(:, b)
        do i = 1, 6
          do l = 1, n
            ia(i, :) = ia(i, :) - u(i, l)*y(l, :)
            pa(i) = pa(i) + u(i, l)*x(l)
          end do
        end do
      end associate
      shift = twist_shift(w%origin(:, b) - w%origin(:, p))
      w%inertia(:, :, p) = w%inertia(:, :, p) + matmul(transpose(shift), matmul(ia, shift))
      w%bias(:, p) = w%bias(:, p) + matmul(transpose(shift), pa)
    end do
    do b = 1, tree%n_bodies
      first = tree%speed_start(b)
      n = tree%speed_start(b + 1) - first
      p = tree%parent(b)
      a = 0
      if (p > 0) a = matmul(twist_shift(w%origin(:, b) - w%origin(:, p)), w%accel(:, p))
      associate (s => w%subspace(:, first:first + n - 1), u => w%u_mat(:, first:first + n - 1), &
                 uv => w%u_vec(first:first + n - 1))
        do j = 1, n
          x(j) = uv(j) - dot_product(u(:, j), a)
        end do
        d = w%d_factor(:, :, b)
        call cholesky_small_solve(n, d, x)
        do j = 1, n
          qdd(tree%speed(first + j - 1)) = x(j)
          a = a + s(:, j)*x(j)
        end do
      end associate
      w%accel(:, b) = a
    end do
  end subroutine articulated_solve

  !> The shift of a twist (omega, v) from a point p to the point p + d:
  !> v' = v + omega x d = v - [d]x omega.
  pure function twist_shift(d) result(x)
    real(wp), intent(in) :: d(3)
    real(wp) :: x(6, 6)
    integer :: i
    x = 0
    do i = 1, 6
      x(i, i) = 1
    end do
    x(4:6, 1:3) = -skew(d)
  end function twist_shift

  !> The lower Cholesky factor of a(1:n, 1:n) in place (n <= 6); failed: the
  !> first column without a positive pivot (0: none).
  pure subroutine cholesky_small(n, a, failed)
    integer, intent(in) :: n
    real(wp), intent(inout) :: a(6, 6)
    integer, intent(out) :: failed
    integer :: i, j
    failed = 0
    do j = 1, n
      a(j, j) = a(j, j) - dot_product(a(j, 1:j - 1), a(j, 1:j - 1))
      if (.not. a(j, j) > 0) then
        failed = j
        return
      end if
      a(j, j) = sqrt(a(j, j))
      do i = j + 1, n
        a(i, j) = (a(i, j) - dot_product(a(i, 1:j - 1), a(j, 1:j - 1)))/a(j, j)
      end do
    end do
  end subroutine cholesky_small

  !> x := A^-1 x with the factor of cholesky_small.
  pure subroutine cholesky_small_solve(n, l, x)
    integer, intent(in) :: n
    real(wp), intent(in) :: l(6, 6)
    real(wp), intent(inout) :: x(6)
    integer :: i
    do i = 1, n
      x(i) = (x(i) - dot_product(l(i, 1:i - 1), x(1:i - 1)))/l(i, i)
    end do
    do i = n, 1, -1
      x(i) = (x(i) - dot_product(l(i + 1:n, i), x(i + 1:n)))/l(i, i)
    end do
  end subroutine cholesky_small_solve
end module kinetostatics_tree
