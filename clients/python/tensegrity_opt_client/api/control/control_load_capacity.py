from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.load_capacity_out import LoadCapacityOut
from ...models.load_capacity_request import LoadCapacityRequest
from ...types import Response


def _get_kwargs(
    *,
    body: LoadCapacityRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/control/load-capacity",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | LoadCapacityOut | None:
    if response.status_code == 200:
        response_200 = LoadCapacityOut.from_dict(response.json())

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
) -> Response[ErrorOut | LoadCapacityOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: LoadCapacityRequest,
) -> Response[ErrorOut | LoadCapacityOut]:
    """How much more tip load a stable pose carries, per direction (a polar curve)

     For each of `directions` evenly spaced unit directions `d`, the dead-load path `F = base + t d` from
    the pose (`start`, a stable equilibrium under `base`; default the least-energy rest configuration)
    followed by arclength continuation until it first loses stability: a fold (snap) or a bifurcation
    (buckling) (`tensegrity_opt.load_capacity`). `loads` is null where the path stays stable up to a
    joint's range bound or `max_load` (`reasons`). Computed within the server's time limit: directions
    not reached answer `reasons: "time_limit"`.

    Args:
        body (LoadCapacityRequest): The largest extra tip load per direction before a stable pose
            loses stability (`load_capacity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | LoadCapacityOut]
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
    body: LoadCapacityRequest,
) -> ErrorOut | LoadCapacityOut | None:
    """How much more tip load a stable pose carries, per direction (a polar curve)

     For each of `directions` evenly spaced unit directions `d`, the dead-load path `F = base + t d` from
    the pose (`start`, a stable equilibrium under `base`; default the least-energy rest configuration)
    followed by arclength continuation until it first loses stability: a fold (snap) or a bifurcation
    (buckling) (`tensegrity_opt.load_capacity`). `loads` is null where the path stays stable up to a
    joint's range bound or `max_load` (`reasons`). Computed within the server's time limit: directions
    not reached answer `reasons: "time_limit"`.

    Args:
        body (LoadCapacityRequest): The largest extra tip load per direction before a stable pose
            loses stability (`load_capacity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | LoadCapacityOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: LoadCapacityRequest,
) -> Response[ErrorOut | LoadCapacityOut]:
    """How much more tip load a stable pose carries, per direction (a polar curve)

     For each of `directions` evenly spaced unit directions `d`, the dead-load path `F = base + t d` from
    the pose (`start`, a stable equilibrium under `base`; default the least-energy rest configuration)
    followed by arclength continuation until it first loses stability: a fold (snap) or a bifurcation
    (buckling) (`tensegrity_opt.load_capacity`). `loads` is null where the path stays stable up to a
    joint's range bound or `max_load` (`reasons`). Computed within the server's time limit: directions
    not reached answer `reasons: "time_limit"`.

    Args:
        body (LoadCapacityRequest): The largest extra tip load per direction before a stable pose
            loses stability (`load_capacity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | LoadCapacityOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: LoadCapacityRequest,
) -> ErrorOut | LoadCapacityOut | None:
    """How much more tip load a stable pose carries, per direction (a polar curve)

     For each of `directions` evenly spaced unit directions `d`, the dead-load path `F = base + t d` from
    the pose (`start`, a stable equilibrium under `base`; default the least-energy rest configuration)
    followed by arclength continuation until it first loses stability: a fold (snap) or a bifurcation
    (buckling) (`tensegrity_opt.load_capacity`). `loads` is null where the path stays stable up to a
    joint's range bound or `max_load` (`reasons`). Computed within the server's time limit: directions
    not reached answer `reasons: "time_limit"`.

    Args:
        body (LoadCapacityRequest): The largest extra tip load per direction before a stable pose
            loses stability (`load_capacity`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | LoadCapacityOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
