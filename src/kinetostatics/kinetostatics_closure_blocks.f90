!> The closure's linear systems split into independent blocks (issue 10,
!> "Structure for many bodies").
!>
!> The unknown rates x = [beta'; sigma'] of a mechanism (dependent coordinates
!> of the loops, dependent rates of the rate constraints) and the equations
!> [g'; c] = 0 come in groups (one loop or one rate constraint: its
!> measurements or outputs and as many unknowns, at the same positions of x
!> and of the rows). Column k of J_x is the velocity pass with x'_k = 1 and
!> every other rate zero. At finalize, from the elements' links
!> (element_links_t), a structural sweep follows that unit rate through the
!> elements: a frame moves with the rigid motion of a class (0: at rest); a
!> joint (`carried`) whose own variables rest carries its input frame's class
!> on; a `relative` element (a measurement between two frames, a slip
!> velocity) whose input frames all move with one rigid motion gives exactly
!> zero (mathematically: g is invariant under it; the full pass gives
!> rounding, e.g. 1e-17, there); anything else starts a class of its own.
!> The rows that move, and backwards from them the elements that feed them,
!> give the column's pass list: for a tower of bodies on bodies the contact
!> variables of body k reach the closure of contact k only (the bodies above
!> move rigidly with body k, their contacts do not see it), so a column costs
!> a few elements instead of all. Groups that share a nonzero entry are one
!> block (connected components); J_x and J_beta are block diagonal, filled,
!> factored and solved block by block (orders <= 12 by the small LU of
!> numerics_linear_algebra).
!>
!> Without known links for every element (or with blocking switched off, for
!> comparison) there is one block and every column passes over every element:
!> the unblocked computation.
module kinetostatics_closure_blocks
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_linear_algebra, only: lu_factor, lu_solve, small_lu_solve, small_lu_solve_3, small_order
  use kinetostatics_state, only: element_box_t, element_links_t, frame_state_t, scalar_state_t, rest_velocities
  implicit none (type, external)
  private
  public :: closure_blocks_t, dense_block_t, element_reach_t, build_closure_blocks, find_element_links, &
    reach_of, downstream_of, feeding, rest_outputs

  !> One block: its members (positions in x and in the rows, ascending: the
  !> dependent coordinates and closure rows first), J_x's block and its LU, and
  !> the LU of its first mb x mb part (J_beta's block).
  type :: dense_block_t
    integer, allocatable :: members(:)
    integer :: mb = 0                       ! members among the dependent coordinates beta
    real(wp), allocatable :: jac(:, :), lu_x(:, :), lu_b(:, :), work(:)
    integer, allocatable :: pivots_x(:), pivots_b(:)
  end type dense_block_t

  !> The links of every element in compressed rows (element e: start(e) to start(e + 1) - 1).
  type :: element_reach_t
    logical :: known = .false.              ! every element's links are known, every state has one writer
    integer, allocatable :: frame_out_start(:), frame_out(:), scalar_out_start(:), scalar_out(:)
    integer, allocatable :: frame_in_start(:), frame_in(:), scalar_in_start(:), scalar_in(:)
    logical, allocatable :: carried(:), relative(:)
    integer, allocatable :: frame_writer(:), scalar_writer(:)   ! element that writes each state (0: none)
  end type element_reach_t

  type :: closure_blocks_t
    logical :: blocked = .false.            ! several blocks / partial passes (else one block, full passes)
    integer :: nx = 0, r = 0
    integer, allocatable :: pass_start(:), pass(:)   ! column k's elements: pass(pass_start(k):pass_start(k+1)-1)
    integer, allocatable :: block_of(:), position(:) ! block of each x and its place among the members
    type(dense_block_t), allocatable :: blocks(:)
    ! the pass lists of the mass matrix (build_mass_columns), compressed rows as above: speed k's
    ! column (first pass, the blocks it moves, second pass); each unknown alone; each normal frame
    ! translated; the elements whose outputs to clear before each of these passes, in their order
    logical :: mass_blocked = .false.
    integer, allocatable :: mass_pass_start(:), mass_pass(:), touched_start(:), touched(:), &
      second_pass_start(:), second_pass(:), unknown_pass_start(:), unknown_pass(:), normal_pass_start(:), &
      normal_pass(:), clear_start(:), clear(:)
  contains
    procedure :: fill, factor, solve, solve_rates, rest_rates, assemble, block_count, build_mass_columns
  end type closure_blocks_t

contains

  !> The links of every element (reach%known false if one is unknown or a
  !> frame or scalar has two writers).
  subroutine find_element_links(elements, n_frames, n_scalars, reach)
    type(element_box_t), intent(in) :: elements(:)
    integer, intent(in) :: n_frames, n_scalars
    type(element_reach_t), intent(out) :: reach
    type(element_links_t) :: links
    integer :: e, n
    n = size(elements)
    allocate (reach%frame_out_start(n + 1), reach%scalar_out_start(n + 1), reach%frame_in_start(n + 1), &
              reach%scalar_in_start(n + 1), reach%carried(n), reach%relative(n))
    allocate (reach%frame_out(0), reach%scalar_out(0), reach%frame_in(0), reach%scalar_in(0))
    allocate (reach%frame_writer(n_frames), reach%scalar_writer(n_scalars))
    reach%frame_writer = 0
    reach%scalar_writer = 0
    reach%known = .true.
    do e = 1, n
      call elements(e)%e%links(links)
      if (.not. links%known) reach%known = .false.
      reach%frame_out_start(e) = size(reach%frame_out) + 1
      reach%scalar_out_start(e) = size(reach%scalar_out) + 1
      reach%frame_in_start(e) = size(reach%frame_in) + 1
      reach%scalar_in_start(e) = size(reach%scalar_in) + 1
      reach%frame_out = [reach%frame_out, links%frames_out]
      reach%scalar_out = [reach%scalar_out, links%scalars_out]
      reach%frame_in = [reach%frame_in, links%frames_in]
      reach%scalar_in = [reach%scalar_in, links%scalars_in]
      reach%carried(e) = links%carried .and. size(links%frames_in) == 1
      reach%relative(e) = links%relative
      if (.not. reach%known) cycle
      if (any(links%frames_out < 1 .or. links%frames_out > n_frames) .or. &
          any(links%scalars_out < 1 .or. links%scalars_out > n_scalars)) then
        reach%known = .false.
        cycle
      end if
      if (any(reach%frame_writer(links%frames_out) /= 0) .or. any(reach%scalar_writer(links%scalars_out) /= 0)) &
        reach%known = .false.
      reach%frame_writer(links%frames_out) = e
      reach%scalar_writer(links%scalars_out) = e
    end do
    reach%frame_out_start(n + 1) = size(reach%frame_out) + 1
    reach%scalar_out_start(n + 1) = size(reach%scalar_out) + 1
    reach%frame_in_start(n + 1) = size(reach%frame_in) + 1
    reach%scalar_in_start(n + 1) = size(reach%scalar_in) + 1
  end subroutine find_element_links

  !> The elements whose position maps read, directly or through other
  !> elements, one of the scalars `sources`, in pass order: after only those
  !> scalars changed, these are the elements whose outputs can change (the
  !> plain data flow of the links, without the rigid-motion shortcuts of
  !> reach_of, which hold for rates only). Every element when a link is unknown.
  function downstream_of(reach, sources, n_frames, n_scalars, n_elements) result(list)
    type(element_reach_t), intent(in) :: reach
    integer, intent(in) :: sources(:), n_frames, n_scalars, n_elements
    integer, allocatable :: list(:)
    logical :: frame_changed(n_frames), scalar_changed(n_scalars), runs(n_elements)
    integer :: e
    if (.not. reach%known) then
      list = [(e, e = 1, n_elements)]
      return
    end if
    frame_changed = .false.
    scalar_changed = .false.
    scalar_changed(sources) = .true.
    do e = 1, n_elements
      runs(e) = any(frame_changed(reach%frame_in(reach%frame_in_start(e):reach%frame_in_start(e + 1) - 1))) .or. &
                any(scalar_changed(reach%scalar_in(reach%scalar_in_start(e):reach%scalar_in_start(e + 1) - 1)))
      if (.not. runs(e)) cycle
      frame_changed(reach%frame_out(reach%frame_out_start(e):reach%frame_out_start(e + 1) - 1)) = .true.
      scalar_changed(reach%scalar_out(reach%scalar_out_start(e):reach%scalar_out_start(e + 1) - 1)) = .true.
    end do
    list = pack([(e, e = 1, n_elements)], runs)
  end function downstream_of

  !> The structural sweep of a unit rate of the scalars `sources` (module
  !> comment), or of a rigid motion of the frames `frame_sources` (their
  !> writers stay at rest): moving(s) for every scalar that moves, live(e) for
  !> every element whose outputs move, frame classes (0: at rest; `classes`
  !> if asked: frames of one class move with one rigid motion).
  subroutine reach_of(reach, sources, n_frames, n_scalars, moving, live, frame_sources, classes)
    type(element_reach_t), intent(in) :: reach
    integer, intent(in) :: sources(:), n_frames, n_scalars
    logical, intent(out) :: moving(n_scalars)
    logical, intent(out) :: live(:)
    integer, intent(in), optional :: frame_sources(:)
    integer, intent(out), optional :: classes(n_frames)
    integer :: frame_class(n_frames), e, c
    logical :: scalars_move, one_motion
    frame_class = 0
    if (present(frame_sources)) frame_class(frame_sources) = -1
    moving = .false.
    moving(sources) = .true.
    live = .false.
    do e = 1, size(live)
      associate (f_in => reach%frame_in(reach%frame_in_start(e):reach%frame_in_start(e + 1) - 1), &
                 s_in => reach%scalar_in(reach%scalar_in_start(e):reach%scalar_in_start(e + 1) - 1), &
                 f_out => reach%frame_out(reach%frame_out_start(e):reach%frame_out_start(e + 1) - 1), &
                 s_out => reach%scalar_out(reach%scalar_out_start(e):reach%scalar_out_start(e + 1) - 1))
        scalars_move = any(moving(s_in))
        if (.not. scalars_move .and. all(frame_class(f_in) == 0)) cycle
        c = 0
        if (size(f_in) > 0) c = frame_class(f_in(1))
        one_motion = .not. scalars_move .and. size(f_in) > 0 .and. all(frame_class(f_in) == c)
        if (one_motion .and. reach%relative(e) .and. size(f_out) == 0) cycle   ! exactly zero outputs
        live(e) = .true.
        if (one_motion .and. reach%carried(e)) then
          frame_class(f_out) = c
        else
          frame_class(f_out) = e
        end if
        if (.not. (one_motion .and. reach%relative(e))) moving(s_out) = .true.
      end associate
    end do
    if (present(classes)) classes = frame_class
  end subroutine reach_of

  !> The blocks of the unknowns `unknowns` (scalar indices of x, the first r
  !> of them the dependent coordinates) with equation rows `rows` (scalar
  !> indices), groups given by their first positions group_start (plus
  !> nx + 1 at the end). blocked = .false. or unknown links: one block,
  !> full passes.
  subroutine build_closure_blocks(self, elements, reach, n_frames, n_scalars, unknowns, rows, r, group_start, &
                                  blocked)
    class(closure_blocks_t), intent(out) :: self
    type(element_box_t), intent(in) :: elements(:)
    type(element_reach_t), intent(in) :: reach
    integer, intent(in) :: n_frames, n_scalars, unknowns(:), rows(:), r, group_start(:)
    logical, intent(in) :: blocked
    integer :: group(size(unknowns)), parent(size(group_start)), k, i, e, g, nblocks, m, nx, n
    logical :: moving(n_scalars), live(size(elements)), need_frame(n_frames), need_scalar(n_scalars)
    nx = size(unknowns)
    n = size(elements)
    self%nx = nx
    self%r = r
    self%blocked = blocked .and. reach%known .and. nx > 0
    allocate (self%pass_start(nx + 1), self%pass(0), self%block_of(nx), self%position(nx))
    do g = 1, size(group_start) - 1
      group(group_start(g):group_start(g + 1) - 1) = g
    end do
    parent = [(g, g = 1, size(parent))]
    do k = 1, nx
      self%pass_start(k) = size(self%pass) + 1
      if (.not. self%blocked) then
        self%pass = [self%pass, [(e, e = 1, n)]]
        cycle
      end if
      call reach_of(reach, [unknowns(k)], n_frames, n_scalars, moving, live)
      ! the rows that move, their groups joined with k's, and the elements that feed them
      need_frame = .false.
      need_scalar = .false.
      do i = 1, nx
        if (.not. moving(rows(i))) cycle
        call join(group(k), group(i))
        need_scalar(rows(i)) = .true.
      end do
      self%pass = [self%pass, feeding(reach, live, need_frame, need_scalar)]
    end do
    self%pass_start(nx + 1) = size(self%pass) + 1

    ! blocks: the groups' components, numbered in order of their first member
    nblocks = 0
    self%block_of = 0
    do k = 1, nx
      g = root(group(k))
      if (self%block_of(k) /= 0) cycle
      nblocks = nblocks + 1
      do i = k, nx
        if (root(group(i)) == g) self%block_of(i) = nblocks
      end do
    end do
    if (.not. self%blocked) self%block_of = min(self%block_of, 1)
    nblocks = maxval([0, self%block_of])
    allocate (self%blocks(nblocks))
    do k = 1, nblocks
      associate (b => self%blocks(k))
        b%members = pack([(i, i = 1, nx)], self%block_of == k)
        m = size(b%members)
        b%mb = count(b%members <= r)
        do i = 1, m
          self%position(b%members(i)) = i
        end do
        allocate (b%jac(m, m), b%lu_x(m, m), b%lu_b(b%mb, b%mb), b%work(m), b%pivots_x(m), b%pivots_b(b%mb))
        b%jac = 0
      end associate
    end do
  contains
    recursive integer function root(a) result(top)
      integer, intent(in) :: a
      top = a
      if (parent(a) /= a) top = root(parent(a))
    end function root
    subroutine join(a, b)
      integer, intent(in) :: a, b
      parent(root(a)) = root(b)
    end subroutine join
  end subroutine build_closure_blocks

  !> The pass lists of the mass matrix and of the normal forces' maps
  !> (kinetostatics_mechanism, dynamics): partial twists of the frames
  !> `tracked` (the mass elements' frames, the scaled laws' load frames) under
  !> three kinds of unit motion at rest, each an acceleration pass over the
  !> elements it moves that feed a tracked frame or a row it needs:
  !> * speed k accelerated by one (column k of M): it moves the elements L(k)
  !>   of the sweep that starts at it and the unknowns of every block whose
  !>   rows move (the blocks B(k), `touched`), until nothing changes; the
  !>   first pass runs over L(k) pruned to what feeds a tracked frame or a row
  !>   of B(k), the second (after the solve of B(k)) over those the unknowns
  !>   of B(k) move that feed a tracked frame (for a tower: k's body and the
  !>   bodies above it). blocked = .false. or unknown links: every element and
  !>   every block (mass_blocked false; the mechanism's full passes);
  !> * unknown k alone (beta'' or sigma'', nothing solved: the partial twists
  !>   of the open chain, whose powers against the inertial wrenches are the
  !>   generalized forces on the unknowns, hence the cut forces): its sweep
  !>   pruned to what feeds a tracked frame (often empty: then no pass);
  !> * frame F = normal_frames(c) translated along its z (the contacts whose
  !>   N is the force on F): the sweep of that rigid motion (F's writer at
  !>   rest), pruned to what feeds a tracked frame or any row.
  !> Between two passes only the outputs of the elements the one before ran
  !> and this one does not must be set back to rest (the others it
  !> overwrites, the rest never moved): `clear`, for the passes in the order
  !> the mechanism runs them (the columns if mass_blocked, then the unknowns'
  !> non-empty passes, then the normal frames'), after a state at rest.
  subroutine build_mass_columns(self, reach, n_frames, n_scalars, speeds, unknowns, rows, tracked, normal_frames, &
                                blocked)
    class(closure_blocks_t), intent(inout) :: self
    type(element_reach_t), intent(in) :: reach
    integer, intent(in) :: n_frames, n_scalars, speeds(:), unknowns(:), rows(:), tracked(:), normal_frames(:)
    logical, intent(in) :: blocked
    logical :: moving(n_scalars), live(size(reach%carried)), live_unknowns(size(reach%carried)), &
      moved(size(self%blocks)), changed, tracked_frame(n_frames), row(n_scalars), no_row(n_scalars), &
      ran(size(reach%carried)), runs(size(reach%carried))
    integer :: k, b, n, nb
    integer, allocatable :: sources(:), pass(:)
    n = size(reach%carried)
    nb = size(self%blocks)
    self%mass_blocked = blocked .and. reach%known
    tracked_frame = .false.
    tracked_frame(tracked) = .true.
    no_row = .false.
    allocate (self%mass_pass_start(size(speeds) + 1), self%touched_start(size(speeds) + 1), &
              self%second_pass_start(size(speeds) + 1), self%unknown_pass_start(size(unknowns) + 1), &
              self%normal_pass_start(size(normal_frames) + 1), self%clear_start(1))
    allocate (self%mass_pass(0), self%touched(0), self%second_pass(0), self%unknown_pass(0), self%normal_pass(0), &
              self%clear(0))
    self%clear_start = 1
    ran = .false.
    do k = 1, size(speeds)
      self%mass_pass_start(k) = size(self%mass_pass) + 1
      self%touched_start(k) = size(self%touched) + 1
      self%second_pass_start(k) = size(self%second_pass) + 1
      if (.not. self%mass_blocked) then
        self%mass_pass = [self%mass_pass, [(b, b = 1, n)]]
        self%touched = [self%touched, [(b, b = 1, nb)]]
        cycle
      end if
      moved = .false.   ! L(k) and B(k): the fixpoint
      sources = [speeds(k)]
      do
        call reach_of(reach, sources, n_frames, n_scalars, moving, live)
        changed = .false.
        do b = 1, nb
          if (moved(b) .or. .not. any(moving(rows(self%blocks(b)%members)))) cycle
          moved(b) = .true.
          changed = .true.
          sources = [sources, unknowns(self%blocks(b)%members)]
        end do
        if (.not. changed) exit
      end do
      row = .false.
      do b = 1, nb
        if (moved(b)) row(rows(self%blocks(b)%members)) = .true.
      end do
      pass = feeding(reach, live, tracked_frame, row)
      self%mass_pass = [self%mass_pass, pass]
      self%touched = [self%touched, pack([(b, b = 1, nb)], moved)]
      call add_clear(pass)
      if (.not. any(moved)) cycle
      call reach_of(reach, sources(2:), n_frames, n_scalars, moving, live_unknowns)
      self%second_pass = [self%second_pass, feeding(reach, live .and. live_unknowns, tracked_frame, no_row)]
    end do
    self%mass_pass_start(size(speeds) + 1) = size(self%mass_pass) + 1
    self%touched_start(size(speeds) + 1) = size(self%touched) + 1
    self%second_pass_start(size(speeds) + 1) = size(self%second_pass) + 1
    if (.not. reach%known) then   ! the mechanism forms M by inverse-dynamics passes
      self%unknown_pass_start = 1
      self%normal_pass_start = 1
      return
    end if
    do k = 1, size(unknowns)
      self%unknown_pass_start(k) = size(self%unknown_pass) + 1
      call reach_of(reach, [unknowns(k)], n_frames, n_scalars, moving, live)
      pass = feeding(reach, live, tracked_frame, no_row)
      self%unknown_pass = [self%unknown_pass, pass]
      if (size(pass) > 0) call add_clear(pass)
    end do
    self%unknown_pass_start(size(unknowns) + 1) = size(self%unknown_pass) + 1
    row = .false.
    row(rows) = .true.
    do k = 1, size(normal_frames)
      self%normal_pass_start(k) = size(self%normal_pass) + 1
      call reach_of(reach, [integer ::], n_frames, n_scalars, moving, live, [normal_frames(k)])
      pass = feeding(reach, live, tracked_frame, row)
      self%normal_pass = [self%normal_pass, pass]
      call add_clear(pass)
    end do
    self%normal_pass_start(size(normal_frames) + 1) = size(self%normal_pass) + 1
  contains
    !> The next pass runs `pass`: clear what the one before ran and this one does not.
    subroutine add_clear(pass)
      integer, intent(in) :: pass(:)
      integer :: e
      runs = .false.
      runs(pass) = .true.
      self%clear = [self%clear, pack([(e, e = 1, n)], ran .and. .not. runs)]
      self%clear_start = [self%clear_start, size(self%clear) + 1]
      ran = runs
    end subroutine add_clear
  end subroutine build_mass_columns

  !> The elements among `live` whose outputs feed, directly or through other
  !> live elements, the frames `frame_wanted` or the scalars `scalar_wanted`,
  !> in pass order.
  function feeding(reach, live, frame_wanted, scalar_wanted) result(list)
    type(element_reach_t), intent(in) :: reach
    logical, intent(in) :: live(:), frame_wanted(:), scalar_wanted(:)
    integer, allocatable :: list(:)
    logical :: need_frame(size(frame_wanted)), need_scalar(size(scalar_wanted)), needed(size(live))
    integer :: e
    need_frame = frame_wanted
    need_scalar = scalar_wanted
    needed = .false.
    do e = size(live), 1, -1
      if (.not. live(e)) cycle
      associate (f_out => reach%frame_out(reach%frame_out_start(e):reach%frame_out_start(e + 1) - 1), &
                 s_out => reach%scalar_out(reach%scalar_out_start(e):reach%scalar_out_start(e + 1) - 1))
        if (.not. (any(need_frame(f_out)) .or. any(need_scalar(s_out)))) cycle
      end associate
      needed(e) = .true.
      need_frame(reach%frame_in(reach%frame_in_start(e):reach%frame_in_start(e + 1) - 1)) = .true.
      need_scalar(reach%scalar_in(reach%scalar_in_start(e):reach%scalar_in_start(e + 1) - 1)) = .true.
    end do
    list = pack([(e, e = 1, size(live))], needed)
  end function feeding

  integer function block_count(self)
    class(closure_blocks_t), intent(in) :: self
    block_count = size(self%blocks)
  end function block_count

  !> Columns 1..last of the blocks' J_x (last = r: J_beta's columns only),
  !> one velocity pass per column over its elements, every other rate zero.
  !> Destroys the velocity state.
  subroutine fill(self, elements, reach, frames, scalars, unknowns, rows, last)
    class(closure_blocks_t), intent(inout) :: self
    type(element_box_t), intent(inout) :: elements(:)
    type(element_reach_t), intent(in) :: reach
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer, intent(in) :: unknowns(:), rows(:), last
    integer :: k, i, j
    call rest_velocities(frames, scalars)
    do k = 1, last
      scalars(unknowns(k))%qd = 1
      do j = self%pass_start(k), self%pass_start(k + 1) - 1
        call elements(self%pass(j))%e%velocity(frames, scalars)
      end do
      associate (b => self%blocks(self%block_of(k)))
        j = self%position(k)
        do i = 1, size(b%members)
          b%jac(i, j) = scalars(rows(b%members(i)))%qd
        end do
      end associate
      scalars(unknowns(k))%qd = 0
      if (.not. self%blocked) cycle
      ! back to rest for the next column: the outputs this one moved
      call rest_outputs(reach, self%pass, self%pass_start(k), self%pass_start(k + 1) - 1, frames, scalars)
    end do
  end subroutine fill

  !> The velocities of the outputs of the elements list(first:last) set to
  !> rest (loops of a few turns: not unrolled, the remainder costs more).
  subroutine rest_outputs(reach, list, first, last, frames, scalars)
    type(element_reach_t), intent(in) :: reach
    integer, intent(in) :: list(:), first, last
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer :: p, l, e
    !GCC$ unroll 1
    do p = first, last
      e = list(p)
      !GCC$ unroll 1
      do l = reach%frame_out_start(e), reach%frame_out_start(e + 1) - 1
        frames(reach%frame_out(l))%omega = 0
        frames(reach%frame_out(l))%v = 0
      end do
      !GCC$ unroll 1
      do l = reach%scalar_out_start(e), reach%scalar_out_start(e + 1) - 1
        scalars(reach%scalar_out(l))%qd = 0
      end do
    end do
  end subroutine rest_outputs

  !> LU of every block's J_beta part (with_rates false) or of its whole J_x
  !> (true); zero_pivot: the position in x of the first zero pivot (0: none).
  subroutine factor(self, with_rates, status, zero_pivot)
    class(closure_blocks_t), intent(inout) :: self
    logical, intent(in) :: with_rates
    type(status_t), intent(inout) :: status
    integer, intent(out) :: zero_pivot
    integer :: k, local
    zero_pivot = 0
    do k = 1, size(self%blocks)
      associate (b => self%blocks(k))
        if (with_rates) then
          b%lu_x = b%jac
          call lu_factor(b%lu_x, b%pivots_x, status, local)
        else
          if (b%mb == 0) cycle
          b%lu_b = b%jac(1:b%mb, 1:b%mb)
          call lu_factor(b%lu_b, b%pivots_b, status, local)
        end if
        if (.not. status%ok()) then
          zero_pivot = 0
          if (local > 0) zero_pivot = b%members(local)
          return
        end if
      end associate
    end do
  end subroutine factor

  !> v := J^-1 v (or J^-T v) in place, J = J_x (with_rates, v of length nx)
  !> or J_beta (v of length r), block by block (only the blocks `only`, the
  !> rest of v untouched). Blocks up to small_order (all of the rider's, the
  !> towers') are solved here with the LU of numerics_linear_algebra, the same
  !> operations in the same order as its small_lu_solve, without the call
  !> through lu_solve and the copies through an assumed-shape work array (the
  !> default run's 161,000 solves of two 3 x 3 blocks each: 6.5 % -> 2.9 % of
  !> its instructions).
  subroutine solve(self, with_rates, v, transpose, only)
    class(closure_blocks_t), intent(inout) :: self
    logical, intent(in) :: with_rates, transpose
    real(wp), intent(inout) :: v(:)
    integer, intent(in), optional :: only(:)
    integer :: k, l, m, n_blocks
    n_blocks = size(self%blocks)
    if (present(only)) n_blocks = min(n_blocks, size(only))
    do l = 1, n_blocks
      k = l
      if (present(only)) k = only(l)
      associate (b => self%blocks(k))
        m = b%mb
        if (with_rates) m = size(b%members)
        if (m == 0) cycle
        if (m <= small_order) then
          if (with_rates) then
            call small_block_solve(b%lu_x, b%pivots_x, m, b%members, v, transpose)
          else
            call small_block_solve(b%lu_b, b%pivots_b, m, b%members, v, transpose)
          end if
          cycle
        end if
        call large_block_solve(b, with_rates, m, v, transpose)
      end associate
    end do
  end subroutine solve

  !> The closure of the blocks `only` solved at rate level (velocity: the
  !> scalars' qd, else their qdd), the other rates as they stand: their
  !> members' rows' rates x(j) = rate(rows(j)), x := J_x^-1 x (with_rates;
  !> else J_beta^-1), and their unknowns' rates rate(unknowns(j)) = -x(j).
  !> x: work space (length nx). (Not an array of the qd or qdd: a copy.)
  subroutine solve_rates(self, with_rates, rows, unknowns, x, scalars, velocity, only)
    class(closure_blocks_t), intent(inout) :: self
    logical, intent(in) :: with_rates, velocity
    integer, intent(in) :: rows(:), unknowns(:), only(:)
    real(wp), intent(inout) :: x(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer :: l, m, j
    do l = 1, size(only)
      do m = 1, size(self%blocks(only(l))%members)
        j = self%blocks(only(l))%members(m)
        if (velocity) then
          x(j) = scalars(rows(j))%qd
        else
          x(j) = scalars(rows(j))%qdd
        end if
      end do
    end do
    call self%solve(with_rates, x, .false., only)
    do l = 1, size(only)
      do m = 1, size(self%blocks(only(l))%members)
        j = self%blocks(only(l))%members(m)
        if (velocity) then
          scalars(unknowns(j))%qd = -x(j)
        else
          scalars(unknowns(j))%qdd = -x(j)
        end if
      end do
    end do
  end subroutine solve_rates

  !> The rates of the unknowns of the blocks `only` set to rest (velocity:
  !> their qd, else their qdd).
  subroutine rest_rates(self, unknowns, scalars, velocity, only)
    class(closure_blocks_t), intent(in) :: self
    integer, intent(in) :: unknowns(:), only(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: velocity
    integer :: l, m
    do l = 1, size(only)
      associate (members => self%blocks(only(l))%members)
        do m = 1, size(members)
          if (velocity) then
            scalars(unknowns(members(m)))%qd = 0
          else
            scalars(unknowns(members(m)))%qdd = 0
          end if
        end do
      end associate
    end do
  end subroutine rest_rates

  !> The same for a block above small_order (LAPACK through lu_solve).
  subroutine large_block_solve(b, with_rates, m, v, transpose)
    type(dense_block_t), intent(inout) :: b
    logical, intent(in) :: with_rates, transpose
    integer, intent(in) :: m
    real(wp), intent(inout) :: v(:)
    type(status_t) :: status
    b%work(1:m) = v(b%members(1:m))
    if (with_rates) then   ! sizes fixed at build: cannot fail
      call lu_solve(b%lu_x, b%pivots_x, b%work(1:m), status, transpose=transpose)
    else
      call lu_solve(b%lu_b, b%pivots_b, b%work(1:m), status, transpose=transpose)
    end if
    v(b%members(1:m)) = b%work(1:m)
  end subroutine large_block_solve

  !> x := A^-1 x or A^-T x for x = v(members(1:m)), m <= small_order, from
  !> P A = L U (lu_factor): small_lu_solve on a local copy (m = 3, a contact
  !> point's loop, the rider's blocks: small_lu_solve_3, its loops unrolled).
  pure subroutine small_block_solve(lu, ipiv, m, members, v, transpose)
    integer, intent(in) :: m
    real(wp), intent(in) :: lu(m, m)
    integer, intent(in) :: ipiv(m), members(m)
    real(wp), intent(inout) :: v(:)
    logical, intent(in) :: transpose
    real(wp) :: x(small_order)
    integer :: i
    if (m == 3) then
      x(1:3) = [v(members(1)), v(members(2)), v(members(3))]
      call small_lu_solve_3(lu, ipiv, x(1:3), transpose)
      v(members(1)) = x(1)
      v(members(2)) = x(2)
      v(members(3)) = x(3)
      return
    end if
    do i = 1, m
      x(i) = v(members(i))
    end do
    call small_lu_solve(lu, ipiv, x(1:m), transpose)
    do i = 1, m
      v(members(i)) = x(i)
    end do
  end subroutine small_block_solve

  !> The full J_beta (with_rates false, r x r) or J_x (nx x nx) from the blocks.
  subroutine assemble(self, with_rates, jac)
    class(closure_blocks_t), intent(in) :: self
    logical, intent(in) :: with_rates
    real(wp), intent(out) :: jac(:, :)
    integer :: k, m
    jac = 0
    do k = 1, size(self%blocks)
      associate (b => self%blocks(k))
        m = b%mb
        if (with_rates) m = size(b%members)
        jac(b%members(1:m), b%members(1:m)) = b%jac(1:m, 1:m)
      end associate
    end do
  end subroutine assemble
end module kinetostatics_closure_blocks
