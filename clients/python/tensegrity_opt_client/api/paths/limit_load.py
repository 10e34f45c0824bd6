from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.limit_load_out import LimitLoadOut
from ...models.limit_load_request import LimitLoadRequest
from ...types import Response


def _get_kwargs(
    *,
    body: LimitLoadRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/limit-load",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | LimitLoadOut | None:
    if response.status_code == 200:
        response_200 = LimitLoadOut.from_dict(response.json())

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
) -> Response[ErrorOut | LimitLoadOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: LimitLoadRequest,
) -> Response[ErrorOut | LimitLoadOut]:
    """The dead load at which the path from a rest configuration loses stability

     The dead-load path `F = t d` from a rest configuration (`start`, default the least-energy one)
    followed until stability is first lost (`tensegrity_opt.limit_load`): `kind` `fold` (snap-through)
    or `bifurcation` (the straight symmetric chain buckles at its critical load, `/v1/buckling`), with
    `load`, the configuration and the mode there; `none` when the path stays stable to a joint limit or
    `max_load` (`status`), with `quasi_buckling_load`, the load of least tangent stiffness along the
    load. `boundary: guided` holds the tip's y (the paper's case). `include_branch` adds the path.
    Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64
    segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (LimitLoadRequest): The dead load where the branch from a rest configuration first
            loses stability (`tensegrity_opt.limit_load`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | LimitLoadOut]
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
    body: LimitLoadRequest,
) -> ErrorOut | LimitLoadOut | None:
    """The dead load at which the path from a rest configuration loses stability

     The dead-load path `F = t d` from a rest configuration (`start`, default the least-energy one)
    followed until stability is first lost (`tensegrity_opt.limit_load`): `kind` `fold` (snap-through)
    or `bifurcation` (the straight symmetric chain buckles at its critical load, `/v1/buckling`), with
    `load`, the configuration and the mode there; `none` when the path stays stable to a joint limit or
    `max_load` (`status`), with `quasi_buckling_load`, the load of least tangent stiffness along the
    load. `boundary: guided` holds the tip's y (the paper's case). `include_branch` adds the path.
    Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64
    segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (LimitLoadRequest): The dead load where the branch from a rest configuration first
            loses stability (`tensegrity_opt.limit_load`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | LimitLoadOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: LimitLoadRequest,
) -> Response[ErrorOut | LimitLoadOut]:
    """The dead load at which the path from a rest configuration loses stability

     The dead-load path `F = t d` from a rest configuration (`start`, default the least-energy one)
    followed until stability is first lost (`tensegrity_opt.limit_load`): `kind` `fold` (snap-through)
    or `bifurcation` (the straight symmetric chain buckles at its critical load, `/v1/buckling`), with
    `load`, the configuration and the mode there; `none` when the path stays stable to a joint limit or
    `max_load` (`status`), with `quasi_buckling_load`, the load of least tangent stiffness along the
    load. `boundary: guided` holds the tip's y (the paper's case). `include_branch` adds the path.
    Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64
    segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (LimitLoadRequest): The dead load where the branch from a rest configuration first
            loses stability (`tensegrity_opt.limit_load`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | LimitLoadOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: LimitLoadRequest,
) -> ErrorOut | LimitLoadOut | None:
    """The dead load at which the path from a rest configuration loses stability

     The dead-load path `F = t d` from a rest configuration (`start`, default the least-energy one)
    followed until stability is first lost (`tensegrity_opt.limit_load`): `kind` `fold` (snap-through)
    or `bifurcation` (the straight symmetric chain buckles at its critical load, `/v1/buckling`), with
    `load`, the configuration and the mode there; `none` when the path stays stable to a joint limit or
    `max_load` (`status`), with `quasi_buckling_load`, the load of least tangent stiffness along the
    load. `boundary: guided` holds the tip's y (the paper's case). `include_branch` adds the path.
    Pseudo-arclength continuation (`tensegrity_opt.analyses.paths.branches`): chains of up to 64
    segments (longer: 422 `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (LimitLoadRequest): The dead load where the branch from a rest configuration first
            loses stability (`tensegrity_opt.limit_load`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | LimitLoadOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
