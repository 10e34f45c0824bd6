from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.branch_request import BranchRequest
from ...models.error_out import ErrorOut
from ...models.traced_branch_out import TracedBranchOut
from ...types import Response


def _get_kwargs(
    *,
    body: BranchRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/branch",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | TracedBranchOut | None:
    if response.status_code == 200:
        response_200 = TracedBranchOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | TracedBranchOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BranchRequest,
) -> Response[ErrorOut | TracedBranchOut]:
    """One equilibrium branch by arclength continuation, with its events

     The branch through `start` followed in the control parameter `t` (`tensegrity_opt.trace_branch`):
    per point `t`, `q`, the tip force, tip, deflection, energy and the Morse index (0: stable); `events`
    are the folds (t turns back: snap-through), branch points (another branch crosses: `/v1/bifurcation-
    diagram` follows it) and the joint limit that ends a branch, each located precisely. `t_max` /
    `t_min` stop it, `stop_at` after the first event (or loss of stability), `direction: -1` leaves the
    start with `t` decreasing. `control` says what `t` moves: `displacement` (the tip along `direction`
    in (dx, dy), `t` a length), `load` (a dead load `base + t direction`), `guided` (the tip's y held,
    `Fx = base_x + t d_x`, `Fy` the guide's reaction: the paper's case), `wall` (the tip on a
    frictionless wall of `normal`), `preload` (the rest lengths along `direction`, 2n numbers, the tip
    `free` under `load` or `held`). `start`: `{"q"}` joint angles, `{"dx", "dy"}` the least-energy
    equilibrium with the tip held there (displacement and held-tip preload controls), or null: the
    least-energy rest configuration. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (BranchRequest): One equilibrium branch by pseudo-arclength continuation
            (`tensegrity_opt.trace_branch`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | TracedBranchOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: BranchRequest,
) -> ErrorOut | TracedBranchOut | None:
    """One equilibrium branch by arclength continuation, with its events

     The branch through `start` followed in the control parameter `t` (`tensegrity_opt.trace_branch`):
    per point `t`, `q`, the tip force, tip, deflection, energy and the Morse index (0: stable); `events`
    are the folds (t turns back: snap-through), branch points (another branch crosses: `/v1/bifurcation-
    diagram` follows it) and the joint limit that ends a branch, each located precisely. `t_max` /
    `t_min` stop it, `stop_at` after the first event (or loss of stability), `direction: -1` leaves the
    start with `t` decreasing. `control` says what `t` moves: `displacement` (the tip along `direction`
    in (dx, dy), `t` a length), `load` (a dead load `base + t direction`), `guided` (the tip's y held,
    `Fx = base_x + t d_x`, `Fy` the guide's reaction: the paper's case), `wall` (the tip on a
    frictionless wall of `normal`), `preload` (the rest lengths along `direction`, 2n numbers, the tip
    `free` under `load` or `held`). `start`: `{"q"}` joint angles, `{"dx", "dy"}` the least-energy
    equilibrium with the tip held there (displacement and held-tip preload controls), or null: the
    least-energy rest configuration. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (BranchRequest): One equilibrium branch by pseudo-arclength continuation
            (`tensegrity_opt.trace_branch`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | TracedBranchOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BranchRequest,
) -> Response[ErrorOut | TracedBranchOut]:
    """One equilibrium branch by arclength continuation, with its events

     The branch through `start` followed in the control parameter `t` (`tensegrity_opt.trace_branch`):
    per point `t`, `q`, the tip force, tip, deflection, energy and the Morse index (0: stable); `events`
    are the folds (t turns back: snap-through), branch points (another branch crosses: `/v1/bifurcation-
    diagram` follows it) and the joint limit that ends a branch, each located precisely. `t_max` /
    `t_min` stop it, `stop_at` after the first event (or loss of stability), `direction: -1` leaves the
    start with `t` decreasing. `control` says what `t` moves: `displacement` (the tip along `direction`
    in (dx, dy), `t` a length), `load` (a dead load `base + t direction`), `guided` (the tip's y held,
    `Fx = base_x + t d_x`, `Fy` the guide's reaction: the paper's case), `wall` (the tip on a
    frictionless wall of `normal`), `preload` (the rest lengths along `direction`, 2n numbers, the tip
    `free` under `load` or `held`). `start`: `{"q"}` joint angles, `{"dx", "dy"}` the least-energy
    equilibrium with the tip held there (displacement and held-tip preload controls), or null: the
    least-energy rest configuration. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (BranchRequest): One equilibrium branch by pseudo-arclength continuation
            (`tensegrity_opt.trace_branch`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | TracedBranchOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: BranchRequest,
) -> ErrorOut | TracedBranchOut | None:
    """One equilibrium branch by arclength continuation, with its events

     The branch through `start` followed in the control parameter `t` (`tensegrity_opt.trace_branch`):
    per point `t`, `q`, the tip force, tip, deflection, energy and the Morse index (0: stable); `events`
    are the folds (t turns back: snap-through), branch points (another branch crosses: `/v1/bifurcation-
    diagram` follows it) and the joint limit that ends a branch, each located precisely. `t_max` /
    `t_min` stop it, `stop_at` after the first event (or loss of stability), `direction: -1` leaves the
    start with `t` decreasing. `control` says what `t` moves: `displacement` (the tip along `direction`
    in (dx, dy), `t` a length), `load` (a dead load `base + t direction`), `guided` (the tip's y held,
    `Fx = base_x + t d_x`, `Fy` the guide's reaction: the paper's case), `wall` (the tip on a
    frictionless wall of `normal`), `preload` (the rest lengths along `direction`, 2n numbers, the tip
    `free` under `load` or `held`). `start`: `{"q"}` joint angles, `{"dx", "dy"}` the least-energy
    equilibrium with the tip held there (displacement and held-tip preload controls), or null: the
    least-energy rest configuration. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (BranchRequest): One equilibrium branch by pseudo-arclength continuation
            (`tensegrity_opt.trace_branch`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | TracedBranchOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
