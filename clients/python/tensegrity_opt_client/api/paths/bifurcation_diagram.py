from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.bifurcation_diagram_out import BifurcationDiagramOut
from ...models.bifurcation_diagram_request import BifurcationDiagramRequest
from ...models.error_out import ErrorOut
from ...types import Response


def _get_kwargs(
    *,
    body: BifurcationDiagramRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/bifurcation-diagram",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> BifurcationDiagramOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = BifurcationDiagramOut.from_dict(response.json())

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
) -> Response[BifurcationDiagramOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BifurcationDiagramRequest,
) -> Response[BifurcationDiagramOut | ErrorOut]:
    """Every branch connected to the start through branch points

     The start's branch both ways (`t` up, then down), then at each branch point both sides of the
    bifurcating branch, recursively to `depth` switches, at most `max_branches` branches
    (`tensegrity_opt.bifurcation_diagram`); each branch as `/v1/branch` answers it. `control` says what
    `t` moves: `displacement` (the tip along `direction` in (dx, dy), `t` a length), `load` (a dead load
    `base + t direction`), `guided` (the tip's y held, `Fx = base_x + t d_x`, `Fy` the guide's reaction:
    the paper's case), `wall` (the tip on a frictionless wall of `normal`), `preload` (the rest lengths
    along `direction`, 2n numbers, the tip `free` under `load` or `held`). `start`: `{"q"}` joint
    angles, `{"dx", "dy"}` the least-energy equilibrium with the tip held there (displacement and held-
    tip preload controls), or null: the least-energy rest configuration. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504. An answer over `TENSEGRITY_MAX_RESPONSE_BYTES` is refused with
    422 `response_too_large` on `max_points`.

    Args:
        body (BifurcationDiagramRequest): Every branch reached from the start through branch
            points (`tensegrity_opt.bifurcation_diagram`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[BifurcationDiagramOut | ErrorOut]
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
    body: BifurcationDiagramRequest,
) -> BifurcationDiagramOut | ErrorOut | None:
    """Every branch connected to the start through branch points

     The start's branch both ways (`t` up, then down), then at each branch point both sides of the
    bifurcating branch, recursively to `depth` switches, at most `max_branches` branches
    (`tensegrity_opt.bifurcation_diagram`); each branch as `/v1/branch` answers it. `control` says what
    `t` moves: `displacement` (the tip along `direction` in (dx, dy), `t` a length), `load` (a dead load
    `base + t direction`), `guided` (the tip's y held, `Fx = base_x + t d_x`, `Fy` the guide's reaction:
    the paper's case), `wall` (the tip on a frictionless wall of `normal`), `preload` (the rest lengths
    along `direction`, 2n numbers, the tip `free` under `load` or `held`). `start`: `{"q"}` joint
    angles, `{"dx", "dy"}` the least-energy equilibrium with the tip held there (displacement and held-
    tip preload controls), or null: the least-energy rest configuration. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504. An answer over `TENSEGRITY_MAX_RESPONSE_BYTES` is refused with
    422 `response_too_large` on `max_points`.

    Args:
        body (BifurcationDiagramRequest): Every branch reached from the start through branch
            points (`tensegrity_opt.bifurcation_diagram`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        BifurcationDiagramOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: BifurcationDiagramRequest,
) -> Response[BifurcationDiagramOut | ErrorOut]:
    """Every branch connected to the start through branch points

     The start's branch both ways (`t` up, then down), then at each branch point both sides of the
    bifurcating branch, recursively to `depth` switches, at most `max_branches` branches
    (`tensegrity_opt.bifurcation_diagram`); each branch as `/v1/branch` answers it. `control` says what
    `t` moves: `displacement` (the tip along `direction` in (dx, dy), `t` a length), `load` (a dead load
    `base + t direction`), `guided` (the tip's y held, `Fx = base_x + t d_x`, `Fy` the guide's reaction:
    the paper's case), `wall` (the tip on a frictionless wall of `normal`), `preload` (the rest lengths
    along `direction`, 2n numbers, the tip `free` under `load` or `held`). `start`: `{"q"}` joint
    angles, `{"dx", "dy"}` the least-energy equilibrium with the tip held there (displacement and held-
    tip preload controls), or null: the least-energy rest configuration. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504. An answer over `TENSEGRITY_MAX_RESPONSE_BYTES` is refused with
    422 `response_too_large` on `max_points`.

    Args:
        body (BifurcationDiagramRequest): Every branch reached from the start through branch
            points (`tensegrity_opt.bifurcation_diagram`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[BifurcationDiagramOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: BifurcationDiagramRequest,
) -> BifurcationDiagramOut | ErrorOut | None:
    """Every branch connected to the start through branch points

     The start's branch both ways (`t` up, then down), then at each branch point both sides of the
    bifurcating branch, recursively to `depth` switches, at most `max_branches` branches
    (`tensegrity_opt.bifurcation_diagram`); each branch as `/v1/branch` answers it. `control` says what
    `t` moves: `displacement` (the tip along `direction` in (dx, dy), `t` a length), `load` (a dead load
    `base + t direction`), `guided` (the tip's y held, `Fx = base_x + t d_x`, `Fy` the guide's reaction:
    the paper's case), `wall` (the tip on a frictionless wall of `normal`), `preload` (the rest lengths
    along `direction`, 2n numbers, the tip `free` under `load` or `held`). `start`: `{"q"}` joint
    angles, `{"dx", "dy"}` the least-energy equilibrium with the tip held there (displacement and held-
    tip preload controls), or null: the least-energy rest configuration. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504. An answer over `TENSEGRITY_MAX_RESPONSE_BYTES` is refused with
    422 `response_too_large` on `max_points`.

    Args:
        body (BifurcationDiagramRequest): Every branch reached from the start through branch
            points (`tensegrity_opt.bifurcation_diagram`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        BifurcationDiagramOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
