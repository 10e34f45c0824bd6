from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.stability_boundary_out import StabilityBoundaryOut
from ...models.stability_boundary_request import StabilityBoundaryRequest
from ...types import Response


def _get_kwargs(
    *,
    body: StabilityBoundaryRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/stability-boundary",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | StabilityBoundaryOut | None:
    if response.status_code == 200:
        response_200 = StabilityBoundaryOut.from_dict(response.json())

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
) -> Response[ErrorOut | StabilityBoundaryOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: StabilityBoundaryRequest,
) -> Response[ErrorOut | StabilityBoundaryOut]:
    """The curve of folds or branch points over a second parameter

     Two-parameter continuation (`tensegrity_opt.analyses.paths.boundaries.stability_boundary`): the
    critical `t` of the one-parameter branches under `control` (a fold or a branch point: `kind` says
    which curve) followed as `parameter` moves from `p_min` to `p_max`, with its cusps; the control's
    references stay fixed (a guide at the start's tip). The limit load an imperfect arm reaches from its
    rest shape is `/v1/imperfection-sensitivity`. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (StabilityBoundaryRequest): The curve of folds or branch points in (parameter, t)
            (`tensegrity_opt.stability_boundary`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | StabilityBoundaryOut]
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
    body: StabilityBoundaryRequest,
) -> ErrorOut | StabilityBoundaryOut | None:
    """The curve of folds or branch points over a second parameter

     Two-parameter continuation (`tensegrity_opt.analyses.paths.boundaries.stability_boundary`): the
    critical `t` of the one-parameter branches under `control` (a fold or a branch point: `kind` says
    which curve) followed as `parameter` moves from `p_min` to `p_max`, with its cusps; the control's
    references stay fixed (a guide at the start's tip). The limit load an imperfect arm reaches from its
    rest shape is `/v1/imperfection-sensitivity`. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (StabilityBoundaryRequest): The curve of folds or branch points in (parameter, t)
            (`tensegrity_opt.stability_boundary`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | StabilityBoundaryOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: StabilityBoundaryRequest,
) -> Response[ErrorOut | StabilityBoundaryOut]:
    """The curve of folds or branch points over a second parameter

     Two-parameter continuation (`tensegrity_opt.analyses.paths.boundaries.stability_boundary`): the
    critical `t` of the one-parameter branches under `control` (a fold or a branch point: `kind` says
    which curve) followed as `parameter` moves from `p_min` to `p_max`, with its cusps; the control's
    references stay fixed (a guide at the start's tip). The limit load an imperfect arm reaches from its
    rest shape is `/v1/imperfection-sensitivity`. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (StabilityBoundaryRequest): The curve of folds or branch points in (parameter, t)
            (`tensegrity_opt.stability_boundary`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | StabilityBoundaryOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: StabilityBoundaryRequest,
) -> ErrorOut | StabilityBoundaryOut | None:
    """The curve of folds or branch points over a second parameter

     Two-parameter continuation (`tensegrity_opt.analyses.paths.boundaries.stability_boundary`): the
    critical `t` of the one-parameter branches under `control` (a fold or a branch point: `kind` says
    which curve) followed as `parameter` moves from `p_min` to `p_max`, with its cusps; the control's
    references stay fixed (a guide at the start's tip). The limit load an imperfect arm reaches from its
    rest shape is `/v1/imperfection-sensitivity`. Pseudo-arclength continuation
    (`tensegrity_opt.analyses.paths.branches`): chains of up to 64 segments (longer: 422
    `invalid_parameter` on `manipulator.n`); `max_points` up to the server's
    `TENSEGRITY_MAX_PATH_POINTS` (default 5000; above: 422 `too_many_points`). The computation stops
    shortly before the server's time limit and answers what it has (200, `status: "time_limit"`,
    `success: false`) instead of a 504.

    Args:
        body (StabilityBoundaryRequest): The curve of folds or branch points in (parameter, t)
            (`tensegrity_opt.stability_boundary`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | StabilityBoundaryOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
