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
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use kinetostatics_state, only: element_box_t, element_links_t, frame_state_t, scalar_state_t
  implicit none (type, external)
  private
  public :: closure_blocks_t, dense_block_t, element_reach_t, build_closure_blocks, find_element_links, &
    reach_of, downstream_of

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
    ! the mass matrix's columns (build_mass_columns): speed k's passes, the blocks it moves, the
    ! speeds j whose entries M(j, k) (and M(k, j)) its column gives; compressed rows as above
    logical :: mass_blocked = .false.
    integer, allocatable :: mass_pass_start(:), mass_pass(:), touched_start(:), touched(:), valid_start(:), &
      valid(:)
  contains
    procedure :: fill, factor, solve, assemble, block_count, build_mass_columns
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
  !> comment): moving(s) for every scalar that moves, live(e) for every
  !> element whose outputs move, frame classes (0: at rest).
  subroutine reach_of(reach, sources, n_frames, n_scalars, moving, live)
    type(element_reach_t), intent(in) :: reach
    integer, intent(in) :: sources(:), n_frames, n_scalars
    logical, intent(out) :: moving(n_scalars)
    logical, intent(out) :: live(:)
    integer :: frame_class(n_frames), e, c
    logical :: scalars_move, one_motion
    frame_class = 0
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
    logical :: moving(n_scalars), live(size(elements)), needed(size(elements)), need_frame(n_frames), &
      need_scalar(n_scalars)
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
      needed = .false.
      do e = n, 1, -1
        if (.not. live(e)) cycle
        associate (f_out => reach%frame_out(reach%frame_out_start(e):reach%frame_out_start(e + 1) - 1), &
                   s_out => reach%scalar_out(reach%scalar_out_start(e):reach%scalar_out_start(e + 1) - 1))
          if (.not. (any(need_frame(f_out)) .or. any(need_scalar(s_out)))) cycle
        end associate
        needed(e) = .true.
        need_frame(reach%frame_in(reach%frame_in_start(e):reach%frame_in_start(e + 1) - 1)) = .true.
        need_scalar(reach%scalar_in(reach%scalar_in_start(e):reach%scalar_in_start(e + 1) - 1)) = .true.
      end do
      self%pass = [self%pass, pack([(e, e = 1, n)], needed)]
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

  !> The mass matrix's columns (kinetostatics_mechanism, dynamics). Speed k
  !> (the scalar speeds(k)) accelerated by one, velocities zero: its motion
  !> moves the elements L(k) of the sweep that starts at it and adds the
  !> unknowns of every block whose rows move (the blocks B(k)), until nothing
  !> changes. Column k gives the entries M(j, k) = M(k, j) of the speeds j
  !> whose own sweep D(j) lies in L(k), apart from the rows of the blocks
  !> (V(k); for a tower: the speeds of k's body and of the bodies above it).
  !> Their generalized forces need the cut forces of the blocks their sweeps
  !> move whose unknowns carry a mass of L(k) (else those cut forces are
  !> zero): with B(k) the blocks N(k), whose unknowns' sweeps and rows join
  !> the force passes. So the two acceleration passes run over L(k), the two
  !> force passes over P(k) = L(k) + the sweeps and rows of N(k). A pair j, k
  !> that neither column gives, with a mass moved by both, makes column k a
  !> full one (every element, every block, every speed), as are all columns
  !> with blocked = .false. (the unblocked computation).
  subroutine build_mass_columns(self, reach, n_frames, n_scalars, speeds, unknowns, rows, blocked)
    class(closure_blocks_t), intent(inout) :: self
    type(element_reach_t), intent(in) :: reach
    integer, intent(in) :: n_frames, n_scalars, speeds(:), unknowns(:), rows(:)
    logical, intent(in) :: blocked
    logical :: moving(n_scalars), live(size(reach%carried), size(speeds)), sweep(size(reach%carried), size(speeds)), &
      unknown_sweep(size(reach%carried), size(unknowns)), moved(size(self%blocks)), needed(size(self%blocks)), &
      opened(size(self%blocks), size(speeds)), full(size(speeds)), changed, leaf(size(reach%carried)), &
      row_writer(size(reach%carried)), in_pass(size(reach%carried)), valid(size(speeds), size(speeds))
    integer :: k, j, b, i, e, n, ns, nb
    integer, allocatable :: sources(:)
    n = size(reach%carried)
    ns = size(speeds)
    nb = size(self%blocks)
    self%mass_blocked = blocked .and. self%blocked
    full = .not. self%mass_blocked
    allocate (self%mass_pass_start(ns + 1), self%touched_start(ns + 1), self%valid_start(ns + 1))
    allocate (self%mass_pass(0), self%touched(0), self%valid(0))
    leaf = reach%frame_out_start(2:) == reach%frame_out_start(:n) .and. &
           reach%scalar_out_start(2:) == reach%scalar_out_start(:n)
    row_writer = .false.
    do i = 1, size(rows)
      if (reach%scalar_writer(rows(i)) > 0) row_writer(reach%scalar_writer(rows(i))) = .true.
    end do
    live = .true.
    valid = .true.
    if (self%mass_blocked) then
      do k = 1, ns   ! D(k) and the blocks whose rows it moves
        call reach_of(reach, [speeds(k)], n_frames, n_scalars, moving, sweep(:, k))
        opened(:, k) = [(any(moving(rows(self%blocks(b)%members))), b = 1, nb)]
      end do
      do i = 1, size(unknowns)
        call reach_of(reach, [unknowns(i)], n_frames, n_scalars, moving, unknown_sweep(:, i))
      end do
      do k = 1, ns   ! L(k): the fixpoint
        moved = .false.
        sources = [speeds(k)]
        do
          call reach_of(reach, sources, n_frames, n_scalars, moving, live(:, k))
          changed = .false.
          do b = 1, nb
            if (moved(b) .or. .not. any(moving(rows(self%blocks(b)%members)))) cycle
            moved(b) = .true.
            changed = .true.
            sources = [sources, unknowns(self%blocks(b)%members)]
          end do
          if (.not. changed) exit
        end do
        valid(:, k) = [(all(.not. sweep(:, j) .or. live(:, k) .or. row_writer), j = 1, ns)]
        ! N(k): B(k) and the blocks the valid speeds open whose unknowns carry a mass of L(k)
        needed = moved
        do b = 1, nb
          if (needed(b) .or. .not. any(opened(b, :) .and. valid(:, k))) cycle
          do i = 1, size(self%blocks(b)%members)
            if (any(unknown_sweep(:, self%blocks(b)%members(i)) .and. live(:, k) .and. leaf)) needed(b) = .true.
          end do
        end do
        in_pass = live(:, k)
        do b = 1, nb
          if (.not. needed(b)) cycle
          do i = 1, size(self%blocks(b)%members)
            in_pass = in_pass .or. unknown_sweep(:, self%blocks(b)%members(i))
            e = reach%scalar_writer(rows(self%blocks(b)%members(i)))
            if (e > 0) in_pass(e) = .true.
          end do
        end do
        ! a speed j is valid if its sweep, apart from the rows of blocks outside N(k), is in the pass
        do j = 1, ns
          if (.not. valid(j, k)) cycle
          do e = 1, n
            if (sweep(e, j) .and. .not. in_pass(e) .and. .not. row_writer(e)) valid(j, k) = .false.
          end do
          do b = 1, nb
            if (.not. needed(b)) cycle
            do i = 1, size(self%blocks(b)%members)
              e = reach%scalar_writer(rows(self%blocks(b)%members(i)))
              if (e > 0) then
                if (sweep(e, j) .and. .not. in_pass(e)) valid(j, k) = .false.
              end if
            end do
          end do
        end do
        self%mass_pass_start(k) = size(self%mass_pass) + 1
        self%touched_start(k) = size(self%touched) + 1
        self%valid_start(k) = size(self%valid) + 1
        self%mass_pass = [self%mass_pass, pack([(e, e = 1, n)], in_pass)]
        self%touched = [self%touched, pack([(b, b = 1, nb)], needed)]
        self%valid = [self%valid, pack([(j, j = 1, ns)], valid(:, k))]
      end do
      do k = 1, ns   ! a pair that neither column gives, with a mass moved by both: column k full
        do j = 1, ns
          if (valid(j, k) .or. valid(k, j)) cycle
          if (any(live(:, j) .and. live(:, k) .and. leaf)) full(k) = .true.
        end do
      end do
      self%mass_pass_start(ns + 1) = size(self%mass_pass) + 1
      ! partial columns leave G incomplete, so the normal forces cost one more pass over every
      ! element: worth it only if the columns save more than that (not for one body: the egg)
      if (count(.not. full)*n - sum(merge(self%mass_pass_start(2:ns + 1) - self%mass_pass_start(1:ns), 0, &
                                           .not. full)) <= n) then
        self%mass_blocked = .false.
        full = .true.
      end if
    end if
    self%mass_pass_start(ns + 1) = size(self%mass_pass) + 1
    self%touched_start(ns + 1) = size(self%touched) + 1
    self%valid_start(ns + 1) = size(self%valid) + 1
    if (.not. any(full)) return
    ! with a full column: lay the lists out again, the full columns covering everything
    block
      integer, allocatable :: pass(:), touched(:), good(:), p0(:), t0(:), v0(:)
      pass = self%mass_pass
      touched = self%touched
      good = self%valid
      p0 = self%mass_pass_start
      t0 = self%touched_start
      v0 = self%valid_start
      self%mass_pass = [integer ::]
      self%touched = [integer ::]
      self%valid = [integer ::]
      do k = 1, ns
        self%mass_pass_start(k) = size(self%mass_pass) + 1
        self%touched_start(k) = size(self%touched) + 1
        self%valid_start(k) = size(self%valid) + 1
        if (full(k)) then
          self%mass_pass = [self%mass_pass, [(e, e = 1, n)]]
          self%touched = [self%touched, [(b, b = 1, nb)]]
          self%valid = [self%valid, [(j, j = 1, ns)]]
        else
          self%mass_pass = [self%mass_pass, pass(p0(k):p0(k + 1) - 1)]
          self%touched = [self%touched, touched(t0(k):t0(k + 1) - 1)]
          self%valid = [self%valid, good(v0(k):v0(k + 1) - 1)]
        end if
      end do
    end block
    self%mass_pass_start(ns + 1) = size(self%mass_pass) + 1
    self%touched_start(ns + 1) = size(self%touched) + 1
    self%valid_start(ns + 1) = size(self%valid) + 1
  end subroutine build_mass_columns

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
    integer :: k, i, e, j
    do k = 1, size(frames)
      frames(k)%omega = 0
      frames(k)%v = 0
    end do
    scalars%qd = 0
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
      do j = self%pass_start(k), self%pass_start(k + 1) - 1
        e = self%pass(j)
        do i = reach%frame_out_start(e), reach%frame_out_start(e + 1) - 1
          frames(reach%frame_out(i))%omega = 0
          frames(reach%frame_out(i))%v = 0
        end do
        do i = reach%scalar_out_start(e), reach%scalar_out_start(e + 1) - 1
          scalars(reach%scalar_out(i))%qd = 0
        end do
      end do
    end do
  end subroutine fill

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
  !> rest of v untouched).
  subroutine solve(self, with_rates, v, transpose, only)
    class(closure_blocks_t), intent(inout) :: self
    logical, intent(in) :: with_rates, transpose
    real(wp), intent(inout) :: v(:)
    integer, intent(in), optional :: only(:)
    type(status_t) :: status
    integer :: k, i, m, l
    do l = 1, size(self%blocks)
      k = l
      if (present(only)) then
        if (l > size(only)) exit
        k = only(l)
      end if
      associate (b => self%blocks(k))
        m = b%mb
        if (with_rates) m = size(b%members)
        if (m == 0) cycle
        do i = 1, m
          b%work(i) = v(b%members(i))
        end do
        if (with_rates) then   ! sizes fixed at build: cannot fail
          call lu_solve(b%lu_x, b%pivots_x, b%work(1:m), status, transpose=transpose)
        else
          call lu_solve(b%lu_b, b%pivots_b, b%work(1:m), status, transpose=transpose)
        end if
        do i = 1, m
          v(b%members(i)) = b%work(i)
        end do
      end associate
    end do
  end subroutine solve

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
